package masl.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.Phaser;

/**
 * Baseline: the thesis's model, one platform thread per agent, each blocked on a {@link Phaser} at
 * every step (the barrier after each instruction of a lock-step block).
 */
final class PhaserThreads implements LockStepRun {

    @Override
    public String name() {
        return "Java threads on a Phaser";
    }

    @Override
    public Callable<Double> prepare(int agents, int steps) {
        return () -> run(agents, steps);
    }

    private static double run(int agents, int steps) throws Exception {
        StepClock clock = new StepClock();
        Phaser barrier = new Phaser(agents) {
            @Override
            protected boolean onAdvance(int phase, int parties) {
                clock.stepEnded();
                return false;
            }
        };
        int[] counters = new int[agents];
        List<Thread> threads = new ArrayList<>(agents);
        for (int agent = 0; agent < agents; agent++) {
            int self = agent;
            Thread thread = new Thread(() -> {
                for (int step = 0; step < steps; step++) {
                    counters[self]++;
                    barrier.arriveAndAwaitAdvance();
                }
            }, "agent-" + agent);
            thread.setDaemon(true);
            threads.add(thread);
        }
        threads.forEach(Thread::start);
        for (Thread thread : threads) {
            thread.join();
        }
        return clock.stepsPerSecond();
    }
}
