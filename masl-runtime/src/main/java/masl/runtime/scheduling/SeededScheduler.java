package masl.runtime.scheduling;

import java.util.List;
import java.util.PriorityQueue;
import java.util.concurrent.Executor;

/**
 * Runs a whole mission on one thread, in an order drawn from a seeded random generator, on a
 * virtual clock: the same program, seed and agents give the same run, trace and journal (the
 * runtime itself makes no arbitrary choice, see {@link Scheduler}). Each slice is one step: the
 * next task to run is drawn among all runnable ones after every step boundary, so different seeds
 * explore different interleavings. The tasks are the agents' slices and the bodies of launched
 * asynchronous primitives ({@link PrimitiveTurn}), so launches complete at reproducible points too.
 *
 * <p>Time is virtual: when nothing is runnable, the clock jumps to the earliest pending
 * {@link #scheduleAfter} action and runs it, so sleeps take no real time. A primitive's sleeps
 * through its agent's services and the mission's call time limit are counted on this clock too
 * ({@link ClockedCall}). A primitive that really blocks for a while ({@code Thread.sleep}) holds
 * the run meanwhile and takes no virtual time. A body that waits for an agent goes on alone
 * ({@link PrimitiveTurn}); such wake-ups, and those from outside the mission (a future completed
 * by another thread), are waited for and break determinism only by when they come.
 */
public final class SeededScheduler implements Scheduler, MissionClock {

    private record Timed(long at, long sequence, Runnable action) { }

    /** Runnable agents' slices and primitives' turns. */
    private final SeededDraw runnable;
    private final PriorityQueue<Timed> timers = new PriorityQueue<>((a, b) -> a.at() != b.at()
            ? Long.compare(a.at(), b.at()) : Long.compare(a.sequence(), b.sequence()));
    /** Virtual milliseconds; volatile so that {@link #nanoTime()} reads it without the lock. */
    private volatile long now;
    private long timerSequence;
    private Thread worker;

    public SeededScheduler(long seed) {
        runnable = new SeededDraw(seed);
    }

    @Override
    public synchronized void start(List<? extends AgentTask> agents) {
        agents.forEach(agent -> runnable.add(agent::runSlice));
        worker = new Thread(this::work, "masl-seeded");
        worker.setDaemon(true);
        worker.start();
    }

    private void work() {
        try {
            // A primitive's turn returns early when interrupted: the flag is still set then.
            while (!Thread.currentThread().isInterrupted()) {
                next().run();
            }
        } catch (InterruptedException missionEnded) {
            // shutdown() interrupts the worker: it ends with the mission.
        }
    }

    /** Draws the next task to run, moving the virtual clock on while none is runnable. */
    private synchronized Runnable next() throws InterruptedException {
        while (runnable.isEmpty()) {
            Timed timed = timers.poll();
            if (timed == null) {
                wait();
            } else {
                now = Math.max(now, timed.at());
                timed.action().run();
            }
        }
        return runnable.draw();
    }

    @Override
    public synchronized void schedule(AgentTask agent) {
        runnable.add(agent::runSlice);
        notifyAll();
    }

    /** The body becomes runnable like an agent, and is drawn among them. */
    @Override
    public synchronized void runPrimitive(Runnable body, Executor threads) {
        runnable.add(new PrimitiveTurn(body, threads)::run);
        notifyAll();
    }

    @Override
    public synchronized void scheduleAfter(long delayMillis, Runnable action) {
        timers.add(new Timed(now + delayMillis, timerSequence++, action));
        notifyAll();
    }

    @Override
    public long millis() {
        return now;
    }

    @Override
    public synchronized void passHeld(long until) {
        now = Math.max(now, until);
    }

    @Override
    public synchronized void runAt(long at, Runnable task) {
        timers.add(new Timed(at, timerSequence++, () -> runnable.add(task)));
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
