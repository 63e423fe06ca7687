package masl.runtime.scheduling;

import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import masl.runtime.Mission;

/**
 * An asynchronous primitive's body as a task of a scheduler that runs a whole mission on one
 * thread in an order of its own ({@link SeededScheduler}, the simulator's lock-step scheduler).
 * The scheduler draws it like an agent's slice and calls {@link #run()}, which waits until the body
 * has returned: the body takes no mission time, and its completion wakes its waiters at a point of
 * the run that the seed fixes.
 *
 * <p>The body itself runs on one of the mission's primitive threads, not on the scheduler's, so
 * that a body that waits for something only the agents can do does not hang the mission: once its
 * thread is seen blocked with no end of its own ({@link Thread.State#WAITING} or
 * {@link Thread.State#BLOCKED}: a latch, a lock, a queue), the turn ends and the body goes on
 * alone; its completion then comes when it comes, like any wake-up from outside, and that run is
 * not reproducible. A timed block ({@code Thread.sleep}, a wait with a timeout) ends by itself:
 * it is waited for, in real time, and takes no mission time (docs/decisions.md). A body that runs
 * its primitive on another thread under a call timeout is judged by that thread's state, so the
 * timeout's own wait does not end the turn early.
 *
 * <p>On a {@link MissionClock}, a body's sleep through its agent's services ends the turn too, but
 * reproducibly: the body resumes as a new turn when the clock gets there ({@link #sleepUntil}). A
 * body blocked without end under a call time limit is interrupted by a turn drawn when the clock
 * reaches the limit ({@link ClockedCall}).
 */
public final class PrimitiveTurn {

    /** How long the scheduler's thread parks between two looks at a body still running. */
    private static final long LOOK_PERIOD_NANOS = TimeUnit.MICROSECONDS.toNanos(50);
    /** How long an interrupted body may take to notice before it is left to go on alone. */
    private static final long INTERRUPTION_GRACE_NANOS = TimeUnit.SECONDS.toNanos(2);

    /** The turn whose body runs on the current thread, for a body that hands its work on. */
    private static final ThreadLocal<PrimitiveTurn> CURRENT = new ThreadLocal<>();

    private final Runnable body;
    private final Executor threads;
    private volatile Thread runner;
    private volatile boolean returned;
    private volatile Thread waiter;
    /** The body waits for a thread it handed its work to (a call timeout): that thread's state counts. */
    private volatile boolean delegating;
    private volatile Thread delegate;
    private volatile boolean delegateDone;
    /** The body sleeps on the mission clock: the turn is over until {@link #resume()}. */
    private volatile boolean asleep;
    /** {@link #resume()} has handed the body its turn and the body has yet to wake: it is not blocked. */
    private volatile boolean waking;
    private final Semaphore wake = new Semaphore(0);
    /** The call the body is in on the mission clock, or null. */
    private volatile ClockedCall call;

    /**
     * @param body    the primitive and the completion of its future
     * @param threads where the body runs, the mission's primitive threads
     */
    public PrimitiveTurn(Runnable body, Executor threads) {
        this.body = body;
        this.threads = threads;
    }

    /**
     * Runs the body and waits, on the calling (scheduler's) thread, until it has returned or blocks
     * without end; returns at once, the body left alone, if that thread is interrupted (the
     * mission is ending).
     */
    public void run() {
        waiter = Thread.currentThread();
        try {
            threads.execute(this::runBody);
        } catch (RejectedExecutionException missionEnded) {
            return;
        }
        awaitBody();
    }

    /** Waits until the body has returned, sleeps on the mission clock, or blocks without end. */
    private void awaitBody() {
        while (!returned && !asleep && !Thread.currentThread().isInterrupted()) {
            if (blockedWithoutEnd()) {
                ClockedCall limited = call;
                if (limited != null) {
                    limited.giveUpAtDeadline(this);
                }
                return;
            }
            LockSupport.parkNanos(this, LOOK_PERIOD_NANOS);
        }
    }

    /**
     * Called on the body's thread: ends this turn and waits until the clock reaches {@code at}
     * and the scheduler draws the body's next turn.
     *
     * @throws InterruptedException when the mission ends meanwhile
     */
    void sleepUntil(MissionClock clock, long at) throws InterruptedException {
        clock.runAt(at, this::resume);
        asleep = true;
        LockSupport.unpark(waiter);
        wake.acquire();
        waking = false;
    }

    /** The body's next turn, on the scheduler's thread: wakes the body and waits for it as {@link #run()} does. */
    void resume() {
        waiter = Thread.currentThread();
        waking = true;
        asleep = false;
        wake.release();
        awaitBody();
    }

    /** The turn drawn when a blocked body's call time limit has passed: interrupts the body, then waits for it. */
    void interruptBody() {
        if (returned || asleep) {
            return;
        }
        waiter = Thread.currentThread();
        Thread body = runner;
        body.interrupt();
        // The body looks blocked until its thread has run again; one that ignores the interruption is left alone in the end.
        long latest = System.nanoTime() + INTERRUPTION_GRACE_NANOS;
        while (!returned && blockedWithoutEnd(body) && System.nanoTime() < latest
                && !Thread.currentThread().isInterrupted()) {
            LockSupport.parkNanos(this, LOOK_PERIOD_NANOS);
        }
        awaitBody();
    }

    void calling(ClockedCall current) {
        call = current;
    }

    private void runBody() {
        runner = Thread.currentThread();
        CURRENT.set(this);
        try {
            body.run();
        } finally {
            CURRENT.remove();
            returned = true;
            LockSupport.unpark(waiter);
        }
    }

    /** The turn whose body runs on the calling thread, or null. <b>Internal:</b> not part of the API. */
    public static PrimitiveTurn current() {
        return CURRENT.get();
    }

    /**
     * The body hands its work to another thread and waits for it ({@link masl.runtime.invocation.PrimitiveCalls#call}
     * under a call timeout): until {@link #delegationEnded()}, the body is blocked without end only
     * if that thread is, and not while it has yet to start or has just finished.
     *
     * <p><b>Internal:</b> not part of the API.
     */
    public void delegating() {
        delegate = null;
        delegateDone = false;
        delegating = true;
    }

    /** Called on the thread the work was handed to, as it starts. <b>Internal:</b> not part of the API. */
    public void delegateStarted() {
        delegate = Thread.currentThread();
    }

    /**
     * Called on the thread the work was handed to, as it finishes: the body is about to go on.
     * <b>Internal:</b> not part of the API.
     */
    public void delegateFinished() {
        delegateDone = true;
    }

    /** Called by the body once it has its result (or gave up waiting for it). <b>Internal:</b> not part of the API. */
    public void delegationEnded() {
        delegating = false;
    }

    /** The state is read before {@link #returned}: a thread back in its pool has returned by then. */
    private boolean blockedWithoutEnd() {
        Thread thread = runner;
        if (delegating) {
            thread = delegateDone ? null : delegate;
        }
        return !waking && blockedWithoutEnd(thread) && !returned;
    }

    /**
     * Whether {@code thread} waits with no end of its own (a latch, a lock, a queue); false for null,
     * and for a thread held while another loads the class it needs: that ends by itself.
     */
    static boolean blockedWithoutEnd(Thread thread) {
        if (thread == null) {
            return false;
        }
        Thread.State state = thread.getState();
        return state == Thread.State.WAITING || state == Thread.State.BLOCKED && !loadingAClass(thread);
    }

    private static boolean loadingAClass(Thread thread) {
        for (StackTraceElement frame : thread.getStackTrace()) {
            if (frame.getMethodName().startsWith("loadClass")) {
                return true;
            }
        }
        return false;
    }
}
