package masl.runtime;

import java.util.ArrayList;
import java.util.List;
import java.util.PriorityQueue;
import java.util.Random;
import java.util.SplittableRandom;

/**
 * Runs a whole mission on one thread, in an order drawn from a seeded random generator, on a
 * virtual clock: the same program, seed and agents give the same run, trace and journal (the
 * runtime itself makes no arbitrary choice, see {@link Scheduler}). Each slice is one step: the
 * next agent to run is drawn among all runnable ones after every step boundary, so different seeds
 * explore different interleavings.
 *
 * <p>Time is virtual: when no agent is runnable, the clock jumps to the earliest pending
 * {@link #scheduleAfter} action and runs it, so sleeps take no real time. A primitive that really
 * blocks blocks the only thread: it must not wait for another agent. Wake-ups from outside the
 * mission (a future completed by another thread) are waited for, and break determinism only by
 * when they come.
 */
public final class SeededScheduler implements Scheduler {

    private record Timed(long at, long sequence, Runnable action) { }

    private final Random random;
    /** Runnable agents; drawn by index, removed by swapping with the last one. */
    private final List<AgentTask> runnable = new ArrayList<>();
    private final PriorityQueue<Timed> timers = new PriorityQueue<>((a, b) -> a.at() != b.at()
            ? Long.compare(a.at(), b.at()) : Long.compare(a.sequence(), b.sequence()));
    /** Virtual milliseconds; volatile so that {@link #nanoTime()} reads it without the lock. */
    private volatile long now;
    private long timerSequence;
    private Thread worker;

    public SeededScheduler(long seed) {
        // Random's first draws for nearby seeds are alike; SplittableRandom spreads the seeds.
        random = new Random(new SplittableRandom(seed).nextLong());
    }

    @Override
    public synchronized void start(List<? extends AgentTask> agents) {
        runnable.addAll(agents);
        worker = new Thread(this::work, "masl-seeded");
        worker.setDaemon(true);
        worker.start();
    }

    private void work() {
        try {
            while (true) {
                next().runSlice();
            }
        } catch (InterruptedException missionEnded) {
            // shutdown() interrupts the worker: it ends with the mission.
        }
    }

    /** Draws the next agent to run, moving the virtual clock on while none is runnable. */
    private synchronized AgentTask next() throws InterruptedException {
        while (runnable.isEmpty()) {
            Timed timed = timers.poll();
            if (timed == null) {
                wait();
            } else {
                now = Math.max(now, timed.at());
                timed.action().run();
            }
        }
        int index = random.nextInt(runnable.size());
        AgentTask drawn = runnable.get(index);
        runnable.set(index, runnable.get(runnable.size() - 1));
        runnable.remove(runnable.size() - 1);
        return drawn;
    }

    @Override
    public synchronized void schedule(AgentTask agent) {
        runnable.add(agent);
        notifyAll();
    }

    @Override
    public synchronized void scheduleAfter(long delayMillis, Runnable action) {
        timers.add(new Timed(now + delayMillis, timerSequence++, action));
        notifyAll();
    }

    /** Virtual time: so a seed reproduces the trace's timestamps too. */
    @Override
    public long nanoTime() {
        return now * 1_000_000L;
    }

    @Override
    public int stepsPerSlice() {
        return 1;
    }

    @Override
    public synchronized void shutdown() {
        if (worker != null) {
            worker.interrupt();
        }
    }
}
