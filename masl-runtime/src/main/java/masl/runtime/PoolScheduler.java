package masl.runtime;

import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * Runs agents as tasks on a small {@link ForkJoinPool} (one worker per core by default): the
 * scalable model (components.md, "Execution model"). A waiting agent holds no thread. A primitive
 * that really blocks should block through {@link Blocking}, which lets the pool add a worker while
 * it blocks, so the other agents keep running.
 *
 * <p><b>Fairness.</b> Runnable agents wait in one FIFO run queue, and each pool task runs the
 * agent at its head. Handing agents to the pool directly would not be fair: a worker runs the
 * tasks it submitted itself before anything submitted from outside, so agents that keep waking
 * each other (or a loop that yields) could starve the agents still waiting for their first slice.
 */
public final class PoolScheduler implements Scheduler {

    private static final int STEPS_PER_SLICE = 128;

    private final ForkJoinPool pool;
    private final ScheduledThreadPoolExecutor timer;
    private final ConcurrentLinkedQueue<AgentTask> runQueue = new ConcurrentLinkedQueue<>();

    /** A pool of one worker per available processor. */
    public PoolScheduler() {
        this(Runtime.getRuntime().availableProcessors());
    }

    public PoolScheduler(int workers) {
        if (workers < 1) {
            throw new IllegalArgumentException("workers: " + workers);
        }
        AtomicInteger count = new AtomicInteger();
        ForkJoinPool.ForkJoinWorkerThreadFactory factory = forkJoinPool -> {
            ForkJoinWorkerThread thread = ForkJoinPool.defaultForkJoinWorkerThreadFactory.newThread(forkJoinPool);
            thread.setName("masl-worker-" + count.incrementAndGet());
            thread.setDaemon(true);
            return thread;
        };
        pool = new ForkJoinPool(workers, factory, null, true);
        timer = new ScheduledThreadPoolExecutor(1, daemon("masl-timer"));
        timer.setRemoveOnCancelPolicy(true);
    }

    @Override
    public void start(List<? extends AgentTask> agents) {
        agents.forEach(this::schedule);
    }

    @Override
    public void schedule(AgentTask agent) {
        runQueue.add(agent);
        // One pool task per queued agent: each runs whichever agent is at the head by then.
        pool.execute(this::runNext);
    }

    private void runNext() {
        runQueue.poll().runSlice();
    }

    @Override
    public void scheduleAfter(long delayMillis, Runnable action) {
        timer.schedule(action, delayMillis, TimeUnit.MILLISECONDS);
    }

    @Override
    public int stepsPerSlice() {
        return STEPS_PER_SLICE;
    }

    @Override
    public void shutdown() {
        timer.shutdownNow();
        pool.shutdownNow();
    }

    static ThreadFactory daemon(String name) {
        return runnable -> {
            Thread thread = new Thread(runnable, name);
            thread.setDaemon(true);
            return thread;
        };
    }
}
