package masl.runtime.scheduling;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.SplittableRandom;

/**
 * The runnable tasks of a deterministic scheduler, drawn one at a time in an order a seed decides:
 * the same seed and the same additions give the same draws. Drawing is by index, the drawn task's
 * place taken by the last one, so a draw costs the same however many tasks wait. Used by
 * {@link SeededScheduler} and by the simulator's lock-step scheduler. Not thread-safe: the
 * scheduler's lock guards it.
 */
public final class SeededDraw {

    private final Random random;
    private final List<Runnable> tasks = new ArrayList<>();

    public SeededDraw(long seed) {
        // Random's first draws for nearby seeds are alike; SplittableRandom spreads the seeds.
        random = new Random(new SplittableRandom(seed).nextLong());
    }

    public void add(Runnable task) {
        tasks.add(task);
    }

    public boolean isEmpty() {
        return tasks.isEmpty();
    }

    /** Removes and returns one of the tasks, drawn at random; there must be one. */
    public Runnable draw() {
        int index = random.nextInt(tasks.size());
        Runnable drawn = tasks.get(index);
        tasks.set(index, tasks.get(tasks.size() - 1));
        tasks.remove(tasks.size() - 1);
        return drawn;
    }
}
