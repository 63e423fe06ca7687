package masl.runtime.scheduling;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.LockSupport;

/**
 * Runs agents as tasks on a small {@link ForkJoinPool} (one worker per core by default): the
 * scalable model (components.md, "Execution model"). A waiting agent holds no thread. A primitive
 * that really blocks should block through {@link Blocking}, which lets the pool add a worker while
 * it blocks, so the other agents keep running.
 *
 * <p><b>Fairness.</b> Runnable agents wait in one FIFO run queue. Handing agents to the pool as
 * tasks of their own would not be fair: a worker runs the tasks it submitted itself before
 * anything submitted from outside, so agents that keep waking each other (or a loop that yields)
 * could starve the agents still waiting for their first slice. Each worker also has a <em>home
 * queue</em> of chunks of agents it parked itself at a barrier, let go by the trip
 * ({@link #scheduleWoken}), which it runs first; those return once per trip, so the common queue
 * waits at most for the current step's chunks, and a worker with nothing else takes another's.
 *
 * <p><b>Runners.</b> The pool does not get a task per slice: at most one <em>runner</em> per
 * worker drains the queues, running the agent at the head until they are empty. So making an
 * agent runnable costs a queue node, not a pool task, and a barrier trip hands its whole wave over
 * as one item ({@link #scheduleAll}, a {@link RunBatch}), which the runners share a chunk of
 * {@value #CHUNK} agents at a time. A runner with nothing to do waits idle in its task, parked,
 * until new work wakes it: the pool's own hand-over of a runner task from a busy worker to an idle
 * one was seen to leave the task queued and the idle worker asleep for whole runs (JDK 17), with
 * one core doing a lock-step mission's work alone. Work queued from outside the runners, or as a
 * wave, wakes an idle runner; an agent that a runner's own slice makes runnable (another agent than
 * the slice's) goes to that runner's <em>hand-over slot</em> and runs right after the slice, up to
 * {@value #HAND_OVERS} in a row, then behind the common queue; the runner wakes another only if more
 * work waits then. So agents that take turns (an invocation and its serving slice, an event and its
 * reaction) cost no thread wake-up and stay on one core, where their state is; through the common
 * queue, both runners contend for its head and a round trip may cross cores (10 pairs of
 * invocations ran at 0.8-2.4 M round trips per second from mission to mission, 2.0-6.0 M with the
 * slot). A runner whose agent blocks in a primitive
 * ({@link Blocking}) stops counting while it blocks, so another runner takes over the queues on the
 * worker the pool adds meanwhile; one counted above {@link #workers} once it returns ends when it
 * next runs out of work.
 *
 * <p><b>Passes.</b> A lock-step block runs as data-parallel passes: a trip lets its wave go as the
 * batches its workers published ({@link WokenBatch}), each worker runs its own in one loop
 * ({@link WokenBatch#run}: each agent woken straight into its slice, its arrival held by the
 * worker's run), and publishes what arrived once, at the end; the last publication trips the
 * barrier. So a step crosses between the cores a few times per batch, not per agent: each worker
 * publishes about {@code ArrivalCombiner.CHUNKS_PER_THREAD} batches per step, and the batches of a
 * wave shorter than {@value #SHARED_FROM} agents are all run by the worker that let them go
 * ({@link #scheduleWoken}), one worker when the pass is too short to share. An agent that blocks,
 * reacts or leaves the block leaves the pass for the ordinary path and rejoins at a later trip.
 *
 * <p><b>Runs of slices.</b> Each worker is a {@link SliceRun}: its slices may defer their
 * arrivals at barriers to it ({@link #currentRun}). A runner flushes it after every
 * {@value #CHUNK} to {@value #MAX_SLICES_PER_FLUSH} slices, as its deferred work asks
 * ({@link SliceRun.Deferred#slicesPerFlush}), when it finds the queues empty (then looks again, as
 * the flush may have tripped a barrier) and before its agent blocks in a primitive. A runner whose
 * own agents wait at a barrier for agents another runner is running spins a moment (up to
 * {@value #SPIN_NANOS} ns) for the trip before it goes idle: in lock-step, a thread wake-up per step
 * would cost more than the step; a pool {@link #forStepsElsewhere} never spins. Nothing else
 * makes a runner spin.
 */
public final class PoolScheduler implements Scheduler {

    private static final int STEPS_PER_SLICE = 128;
    /**
     * The agents a runner claims of a batch at once, and the fewest slices it runs between two
     * flushes of its run: small enough that two runners share a wave of a few hundred agents evenly.
     */
    private static final int CHUNK = 32;
    /**
     * The most slices a runner runs between two flushes of its run, whatever its deferred work asks
     * ({@link SliceRun.Deferred#slicesPerFlush}): the longest an arrival it holds waits for it.
     */
    private static final int MAX_SLICES_PER_FLUSH = 4_096;
    /** How long a runner that ran out of work waits for another runner's trip before it stops. */
    private static final long SPIN_NANOS = 100_000;
    /**
     * Slices a runner runs in a row from its hand-over slot ({@link PoolWorker#handsOver}) before the
     * agents its slices make runnable go to the common queue again, behind those waiting there.
     */
    static final int HAND_OVERS = CHUNK;
    /**
     * The wave from which the batches a trip lets go are shared among the workers, each run by its
     * home worker: those of a shorter wave are all run by the thread that let them go, since
     * handing a batch to another core costs a few cache-line crossings (up to a few microseconds
     * where the cores are far apart), more than that core would save by running its share.
     */
    private static final int SHARED_FROM = 8 * CHUNK;

    private final ForkJoinPool pool;
    private final int workers;
    /** How long a runner that ran out of work waits for another runner's trip: {@link #SPIN_NANOS} or 0. */
    private final long spinNanos;
    private final ScheduledThreadPoolExecutor timer;
    /** {@link AgentTask}s, {@link RunBatch}es and {@link WokenBatch}es, in the order they were made runnable. */
    final ConcurrentLinkedQueue<Object> runQueue = new ConcurrentLinkedQueue<>();
    /** The runs of the pool's live workers, whose home queues hold the rest of the runnable work. */
    final List<SliceRun> runs = new CopyOnWriteArrayList<>();
    /** Runners submitted and not blocked in a primitive, idle ones included: at most {@link #workers} are started. */
    private final AtomicInteger runners = new AtomicInteger();
    /** Runners waiting, in their task, for work: woken before any new runner is started. */
    private final ConcurrentLinkedQueue<PoolWorker> idle = new ConcurrentLinkedQueue<>();
    private final Runnable runner = this::drainRunQueue;
    /** The wave the calling thread is making runnable in {@link #together}, if any. */
    private final ThreadLocal<Together> together = new ThreadLocal<>();
    private volatile boolean shutDown;

    /** A pool of one worker per available processor. */
    public PoolScheduler() {
        this(Runtime.getRuntime().availableProcessors());
    }

    public PoolScheduler(int workers) {
        this(workers, SPIN_NANOS);
    }

    /**
     * A pool of one worker per available processor for agents whose steps run elsewhere (deployed
     * agents' stand-ins): a runner never spins for a trip, since the arrivals that make it come from
     * another JVM, a round trip later, far longer than a spin, whose CPU the other JVMs would lack.
     */
    public static PoolScheduler forStepsElsewhere() {
        return new PoolScheduler(Runtime.getRuntime().availableProcessors(), 0);
    }

    private PoolScheduler(int workers, long spinNanos) {
        if (workers < 1) {
            throw new IllegalArgumentException("workers: " + workers);
        }
        this.workers = workers;
        this.spinNanos = spinNanos;
        AtomicInteger count = new AtomicInteger();
        ForkJoinPool.ForkJoinWorkerThreadFactory factory = forkJoinPool -> {
            PoolWorker thread = new PoolWorker(forkJoinPool, this);
            runs.add(thread.run);
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
        PoolWorker worker = ownWorker();
        if (worker != null && worker.handsOver(agent)) {
            return;
        }
        if (worker == null) {
            Together wave = together.get();
            if (wave != null) {
                wave.agents.add(agent);
                return;
            }
        }
        runQueue.add(agent);
        // A runner's own slice hands its agent over: that runner takes it once the slice ends, and
        // wakes another only if more work waits then (runAlone). Waking one now would cost a
        // thread wake-up per invocation or event for nothing when the agents take turns.
        if (worker == null || worker.blockedCalls > 0) {
            startRunnerIfNeeded();
        }
    }

    /**
     * Queues the agents {@code work} makes runnable as one batch once it returns, and wakes the
     * runners the wave wants then ({@link #scheduleAll}): the runners share it a chunk at a time,
     * and none is woken for each agent, a thread wake-up each.
     */
    @Override
    public void together(Runnable work) {
        if (ownWorker() != null || together.get() != null) {
            work.run();
            return;
        }
        Together wave = new Together();
        together.set(wave);
        try {
            work.run();
        } finally {
            together.remove();
            scheduleAll(wave.agents);
        }
    }

    /** How many runners wait, idle, for work. */
    int idleRunners() {
        return idle.size();
    }

    /** The agents a thread outside the pool made runnable in {@link #together}. */
    private static final class Together {
        final List<AgentTask> agents = new ArrayList<>();
    }

    /** Appends the whole wave to the run queue as one item, then starts the runners it needs. */
    @Override
    public void scheduleAll(List<? extends AgentTask> agents) {
        if (agents.isEmpty()) {
            return;
        }
        runQueue.add(agents.size() == 1 ? agents.get(0) : new RunBatch(agents));
        startRunnersFor(agents.size());
    }

    /** Wakes or starts the runners a wave of {@code agents} queued wants: one per chunk of it, at most one per worker. */
    private void startRunnersFor(int agents) {
        int wanted = Math.min(workers, (agents + CHUNK - 1) / CHUNK);
        int started = 0;
        while (started < wanted && startRunnerIfNeeded()) {
            started++;
        }
    }

    @Override
    public SliceRun currentRun() {
        PoolWorker worker = ownWorker();
        return worker == null ? null : worker.run;
    }

    /** The calling thread if it is one of this pool's workers, else null. */
    private PoolWorker ownWorker() {
        return Thread.currentThread() instanceof PoolWorker worker && worker.scheduler == this ? worker : null;
    }

    /** Wakes another runner if the common queue holds work, which would otherwise wait for this runner. */
    private void shareCommonQueue() {
        if (!runQueue.isEmpty()) {
            startRunnerIfNeeded();
        }
    }

    /**
     * Wakes an idle runner, or starts one unless {@link #workers} are counted already; true if it
     * woke or started one.
     */
    boolean startRunnerIfNeeded() {
        PoolWorker sleeper = idle.poll();
        if (sleeper != null) {
            sleeper.wake();
            return true;
        }
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

    /**
     * A runner's life: runs slices while there is work, then waits idle, in its task, until work
     * wakes it ({@link #startRunnerIfNeeded}); it ends only with the pool, or if it is surplus
     * (started while another runner was blocked, which has come back).
     */
    private void drainRunQueue() {
        PoolWorker self = (PoolWorker) Thread.currentThread();
        boolean counted = true;
        try {
            while (!shutDown) {
                self.inRun = true;
                try {
                    runUntilEmpty(self);
                } finally {
                    self.inRun = false;
                }
                if (leaveIfSurplus()) {
                    counted = false;
                    return;
                }
                idleUntilWoken(self);
            }
        } finally {
            // Also when a slice throws (a runtime bug): no deferred arrival is left behind, and
            // the count must not keep a dead runner.
            try {
                self.run.flush();
            } finally {
                if (counted) {
                    runners.decrementAndGet();
                }
            }
        }
    }

    /** Counts the calling runner out if more than {@link #workers} are counted; true if it did. */
    private boolean leaveIfSurplus() {
        while (true) {
            int running = runners.get();
            if (running <= workers) {
                return false;
            }
            if (runners.compareAndSet(running, running - 1)) {
                return true;
            }
        }
    }

    /**
     * Waits, still counted, until {@link #startRunnerIfNeeded} wakes this runner or the pool shuts
     * down. Work queued after the runner's last look but before it was listed idle found no idle
     * runner to wake, so the runner looks once more after listing itself, and takes itself back.
     */
    private void idleUntilWoken(PoolWorker self) {
        self.woken = false;
        idle.add(self);
        if ((hasWork() || shutDown) && idle.remove(self)) {
            return;
        }
        while (!self.woken && !shutDown) {
            LockSupport.park(this);
            // An interrupt left by a slice's code must not turn this wait into a spin.
            Thread.interrupted();
        }
    }

    /**
     * Runs slices until no queue has work and the run has nothing left to flush: first the agent in
     * its hand-over slot, then the batches of its own home queue, then the common queue's head, then
     * another worker's home batch.
     */
    private void runUntilEmpty(PoolWorker self) {
        SliceRun run = self.run;
        int sinceFlush = 0;
        int flushEvery = slicesPerFlush(run);
        while (!shutDown) {
            AgentTask handedOver = self.takeHandOver();
            WokenBatch own;
            Object head;
            if (handedOver != null) {
                shareCommonQueue();
                sinceFlush += runSlice(self, handedOver);
            } else if ((own = run.homeQueue.poll()) != null) {
                // The common queue would wait for this worker's whole step.
                shareCommonQueue();
                sinceFlush += runWoken(self, own);
            } else if ((head = runQueue.peek()) != null) {
                if (head instanceof RunBatch batch) {
                    sinceFlush += runChunk(self, batch);
                } else if (head instanceof WokenBatch batch) {
                    sinceFlush += runQueue.remove(batch) ? runWoken(self, batch) : 0;
                } else {
                    sinceFlush += runAlone(self, (AgentTask) head);
                }
            } else {
                WokenBatch stolen = stealFrom(run);
                if (stolen != null) {
                    sinceFlush += runWoken(self, stolen);
                } else {
                    if (!run.flush() && !awaitAnotherRunnersWork(run)) {
                        return;
                    }
                    sinceFlush = 0;
                    flushEvery = slicesPerFlush(run);
                }
            }
            if (sinceFlush >= flushEvery) {
                run.flush();
                sinceFlush = 0;
                flushEvery = slicesPerFlush(run);
            }
        }
    }

    /** The slices to run before the next flush of {@code run}: what its deferred work asks, within bounds. */
    private int slicesPerFlush(SliceRun run) {
        return Math.max(CHUNK, Math.min(MAX_SLICES_PER_FLUSH, run.slicesPerFlush(workers)));
    }

    /** A batch of another worker's home queue, or null if none has one. */
    private WokenBatch stealFrom(SliceRun thief) {
        for (SliceRun other : runs) {
            if (other != thief) {
                WokenBatch batch = other.homeQueue.poll();
                if (batch != null) {
                    return batch;
                }
            }
        }
        return null;
    }

    /** Whether any queue, common or home, holds work. */
    private boolean hasWork() {
        if (!runQueue.isEmpty()) {
            return true;
        }
        for (SliceRun run : runs) {
            if (!run.homeQueue.isEmpty()) {
                return true;
            }
        }
        return false;
    }

    /**
     * With the queue empty, while the agents this runner ran wait at a barrier for agents another
     * runner is running (lock-step), spins a moment for the trip that will queue the next wave: a
     * worker that went idle would cost a wake-up of its thread per step. Nothing else makes a
     * runner spin: agents that wait for an answer, a release or a change may wait long. True if
     * work came, false if the runner should stop.
     */
    private boolean awaitAnotherRunnersWork(SliceRun run) {
        if (spinNanos == 0) {
            return hasWork();
        }
        long deadline = System.nanoTime() + spinNanos;
        while (runners.get() - idle.size() > 1 && !shutDown && run.awaitsOthers()) {
            for (int i = 0; i < 64; i++) {
                if (hasWork()) {
                    return true;
                }
                Thread.onSpinWait();
            }
            if (System.nanoTime() - deadline > 0) {
                return false;
            }
        }
        return hasWork();
    }

    /** Claims a chunk of the batch at the head of the queue and runs it; returns how many slices it ran. */
    private int runChunk(PoolWorker self, RunBatch batch) {
        int from = batch.claim(CHUNK);
        int to = Math.min(from + CHUNK, batch.size());
        if (to == batch.size()) {
            // The last chunk is claimed: what was queued after the batch may start, on another runner.
            runQueue.remove(batch);
        }
        for (int i = from; i < to; i++) {
            runSlice(self, batch.get(i));
        }
        return to - from;
    }

    /** Wakes the agents of a batch this runner has taken and runs their slices; returns how many. */
    private int runWoken(PoolWorker self, WokenBatch batch) {
        return batch.run(self);
    }

    /** Runs one slice of {@code agent} on {@code self}, which knows meanwhile whose slice it runs; returns 1. */
    static int runSlice(PoolWorker self, AgentTask agent) {
        self.running = agent;
        try {
            agent.runSlice();
        } finally {
            self.running = null;
        }
        return 1;
    }

    /**
     * Moves the agent in the runner's hand-over slot, if any, to the common queue. The callers start
     * a runner for it next, once this one no longer counts (a runner that blocks, a worker that ends).
     */
    void releaseHandOver(PoolWorker self) {
        AgentTask handedOver = self.takeHandOver();
        if (handedOver != null) {
            runQueue.add(handedOver);
        }
    }

    /**
     * Queues the batch on its home worker, whose runner takes it first (the agents' state is still
     * in that core's cache), or on the common queue if it has no home. A home whose worker has
     * ended is closed, and what comes to it moves on to the common queue. A batch of a wave shorter
     * than {@value #SHARED_FROM} agents let go by a runner's own slices or flush stays with that
     * runner, whatever its home.
     */
    @Override
    public void scheduleWoken(WokenBatch batch) {
        PoolWorker worker = ownWorker();
        if (worker != null && worker.inRun && batch.wave() < SHARED_FROM) {
            // Too short a pass to share: the runner that tripped runs it before it goes idle, and
            // wakes no other, which would only steal it.
            worker.run.homeQueue.add(batch);
            return;
        }
        SliceRun home = batch.home();
        if (home != null) {
            home.homeQueue.add(batch);
            if (home.closed) {
                moveToCommonQueue(home);
            }
        } else {
            runQueue.add(batch);
        }
        startRunnerIfNeeded();
    }

    /**
     * Moves what a closed run's home queue holds to the common queue. Both the worker that closes
     * it and a {@link #scheduleWoken} that finds it closed after adding call this, so nothing
     * queued there is left behind.
     */
    void moveToCommonQueue(SliceRun closed) {
        WokenBatch batch;
        while ((batch = closed.homeQueue.poll()) != null) {
            runQueue.add(batch);
        }
    }

    /** Takes the agent at the head of the queue, unless another runner did, and runs its slice. */
    private int runAlone(PoolWorker self, AgentTask agent) {
        if (!runQueue.remove(agent)) {
            return 0;
        }
        shareCommonQueue();
        return runSlice(self, agent);
    }

    /** The current runner is about to block in a primitive: another may take over the queue. */
    private void runnerBlocks() {
        runners.decrementAndGet();
        if (hasWork()) {
            startRunnerIfNeeded();
        }
    }

    /** The current runner's primitive has returned: it counts again (possibly one above the limit, briefly). */
    private void runnerUnblocked() {
        runners.incrementAndGet();
    }

    /** Called by {@link Blocking} around a call that blocks its thread. */
    static void blocking(boolean starts) {
        if (Thread.currentThread() instanceof PoolWorker worker) {
            if (starts) {
                // Agents whose arrivals the run holds, or that it would run next, must not wait for
                // however long this blocks.
                worker.scheduler.releaseHandOver(worker);
                worker.run.flush();
                worker.blockedCalls++;
                worker.scheduler.runnerBlocks();
            } else {
                worker.blockedCalls--;
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
        for (PoolWorker sleeper : idle) {
            sleeper.wake();
        }
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
