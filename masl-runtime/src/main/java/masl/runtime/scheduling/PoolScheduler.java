package masl.runtime.scheduling;

import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.RejectedExecutionException;
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
 * <p><b>Fairness.</b> Runnable agents wait in one FIFO run queue. Handing agents to the pool as
 * tasks of their own would not be fair: a worker runs the tasks it submitted itself before
 * anything submitted from outside, so agents that keep waking each other (or a loop that yields)
 * could starve the agents still waiting for their first slice.
 *
 * <p><b>Runners.</b> The pool does not get a task per slice: at most one <em>runner</em> per
 * worker drains the run queue, running the agent at its head until the queue is empty. So making
 * an agent runnable costs a queue node, not a pool task and a wake-up of an idle worker, and a
 * barrier trip hands its whole wave over in one pass ({@link #scheduleAll}). A runner whose
 * agent blocks in a primitive ({@link Blocking}) stops counting while it blocks, so another
 * runner takes over the queue on the worker the pool adds meanwhile.
 */
public final class PoolScheduler implements Scheduler {

    private static final int STEPS_PER_SLICE = 128;

    private final ForkJoinPool pool;
    private final int workers;
    private final ScheduledThreadPoolExecutor timer;
    private final ConcurrentLinkedQueue<AgentTask> runQueue = new ConcurrentLinkedQueue<>();
    /** Runners submitted and not blocked in a primitive: at most {@link #workers} are started. */
    private final AtomicInteger runners = new AtomicInteger();
    private final Runnable runner = this::drainRunQueue;
    private volatile boolean shutDown;

    /** A pool of one worker per available processor. */
    public PoolScheduler() {
        this(Runtime.getRuntime().availableProcessors());
    }

    public PoolScheduler(int workers) {
        if (workers < 1) {
            throw new IllegalArgumentException("workers: " + workers);
        }
        this.workers = workers;
        AtomicInteger count = new AtomicInteger();
        ForkJoinPool.ForkJoinWorkerThreadFactory factory = forkJoinPool -> {
            Worker thread = new Worker(forkJoinPool, this);
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
        scheduleAll(agents);
    }

    @Override
    public void schedule(AgentTask agent) {
        runQueue.add(agent);
        startRunnerIfNeeded();
    }

    /** Appends the whole wave to the run queue at once, then starts the runners it needs. */
    @Override
    public void scheduleAll(List<? extends AgentTask> agents) {
        if (agents.isEmpty()) {
            return;
        }
        runQueue.addAll(agents);
        int wanted = Math.min(workers, agents.size());
        int started = 0;
        while (started < wanted && startRunnerIfNeeded()) {
            started++;
        }
    }

    /** Starts a runner unless {@link #workers} are running already; true if it started one. */
    private boolean startRunnerIfNeeded() {
        while (true) {
            int running = runners.get();
            if (running >= workers || shutDown) {
                return false;
            }
            if (runners.compareAndSet(running, running + 1)) {
                return submitRunner();
            }
        }
    }

    private boolean submitRunner() {
        try {
            pool.execute(runner);
            return true;
        } catch (RejectedExecutionException missionEnded) {
            runners.decrementAndGet();
            return false;
        }
    }

    private void drainRunQueue() {
        do {
            try {
                AgentTask agent;
                while (!shutDown && (agent = runQueue.poll()) != null) {
                    agent.runSlice();
                }
            } finally {
                // Also when a slice throws (a runtime bug): the count must not keep a dead runner.
                runners.decrementAndGet();
            }
            // An agent queued after the last poll saw this runner still counted and started none.
        } while (!runQueue.isEmpty() && !shutDown && claimRunner());
    }

    /** Counts the calling runner again, if fewer than {@link #workers} are counted. */
    private boolean claimRunner() {
        while (true) {
            int running = runners.get();
            if (running >= workers) {
                return false;
            }
            if (runners.compareAndSet(running, running + 1)) {
                return true;
            }
        }
    }

    /** The current runner is about to block in a primitive: another may take over the queue. */
    private void runnerBlocks() {
        runners.decrementAndGet();
        if (!runQueue.isEmpty()) {
            startRunnerIfNeeded();
        }
    }

    /** The current runner's primitive has returned: it counts again (possibly one above the limit, briefly). */
    private void runnerUnblocked() {
        runners.incrementAndGet();
    }

    /** Called by {@link Blocking} around a call that blocks its thread. */
    static void blocking(boolean starts) {
        if (Thread.currentThread() instanceof Worker worker) {
            if (starts) {
                worker.scheduler.runnerBlocks();
            } else {
                worker.scheduler.runnerUnblocked();
            }
        }
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
        shutDown = true;
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

    /** A worker of one scheduler's pool: lets {@link Blocking} find the runner it runs. */
    private static final class Worker extends ForkJoinWorkerThread {
        final PoolScheduler scheduler;

        Worker(ForkJoinPool pool, PoolScheduler scheduler) {
            super(pool);
            this.scheduler = scheduler;
        }
    }
}
