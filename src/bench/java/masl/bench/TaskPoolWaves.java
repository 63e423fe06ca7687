package masl.bench;

import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Baseline: the waves of a lock-step block written by hand as tasks on a pool of two threads (the
 * practical limit of this kind of machine). Each step runs one task per agent doing a trivial
 * instruction; the last task of a step to finish starts the next step, which is the barrier.
 */
final class TaskPoolWaves implements LockStepRun {

    private static final int WORKERS = 2;

    @Override
    public String name() {
        return "Java tasks, 2-thread pool";
    }

    @Override
    public Callable<Double> prepare(int agents, int steps) {
        return () -> run(agents, steps);
    }

    private static double run(int agents, int steps) throws Exception {
        ExecutorService pool = Executors.newFixedThreadPool(WORKERS);
        try {
            int[] counters = new int[agents];
            AtomicInteger pending = new AtomicInteger();
            AtomicInteger stepsDone = new AtomicInteger();
            StepClock clock = new StepClock();
            CompletableFuture<Void> finished = new CompletableFuture<>();
            Runnable[] wave = new Runnable[1];
            wave[0] = () -> {
                pending.set(agents);
                for (int agent = 0; agent < agents; agent++) {
                    int self = agent;
                    pool.execute(() -> {
                        counters[self]++;
                        if (pending.decrementAndGet() == 0) {
                            clock.stepEnded();
                            if (stepsDone.incrementAndGet() == steps) {
                                finished.complete(null);
                            } else {
                                wave[0].run();
                            }
                        }
                    });
                }
            };
            wave[0].run();
            finished.get();
            return clock.stepsPerSecond();
        } finally {
            pool.shutdown();
            pool.awaitTermination(10, TimeUnit.SECONDS);
        }
    }
}
