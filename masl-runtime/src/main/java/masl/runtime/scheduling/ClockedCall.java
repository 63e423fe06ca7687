package masl.runtime.scheduling;

import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * A primitive's call on a {@link MissionClock}: its sleeps through its agent's services take mission
 * time, and its call time limit is counted on that clock, so that a seed names one run whatever
 * the machine's speed (docs/decisions.md, "seeded call time limits").
 *
 * <ul>
 * <li>In a {@link PrimitiveTurn} (an asynchronous primitive's body), a sleep ends the turn and the
 *     body resumes as a new turn when the clock gets there; other tasks run meanwhile.
 * <li>Held (called in an agent's slice, which holds the run), a sleep moves the clock on at once.
 * <li>A sleep that would end past the limit ends at the limit instead and throws
 *     {@link InterruptedException}, as a limit's interruption does in real time; the call then
 *     passed its limit ({@link LimitPassed}) whatever the primitive returns.
 * <li>A primitive blocked without end (a latch, a lock: see {@link PrimitiveTurn}) passes its limit
 *     too: in a turn, a turn drawn when the clock reaches the limit interrupts it; held, nothing
 *     else can move, so the clock moves to the limit at once.
 * </ul>
 * The primitive's own Java time (computing, {@code Thread.sleep}) takes no mission time.
 */
public final class ClockedCall {

    /** How long a held call's waiting thread parks between two looks at the primitive. */
    private static final long LOOK_PERIOD_NANOS = TimeUnit.MICROSECONDS.toNanos(50);

    /** The call whose primitive runs on the current thread, for its sleeps. */
    private static final ThreadLocal<ClockedCall> CURRENT = new ThreadLocal<>();

    private final MissionClock clock;
    /** The turn the body runs in; null when the call holds the run. */
    private final PrimitiveTurn turn;
    /** Mission milliseconds by which the call must end; {@link Long#MAX_VALUE} without a limit. */
    private final long deadline;
    private volatile boolean passed;
    private volatile boolean finished;

    private ClockedCall(MissionClock clock, PrimitiveTurn turn, long deadline) {
        this.clock = clock;
        this.turn = turn;
        this.deadline = deadline;
    }

    /**
     * Runs {@code call}, a primitive's Java code, on the clock: on the calling thread, or, when it
     * holds the run under a limit, on one of {@code threads} so that a primitive blocked without
     * end can be given up.
     *
     * @param limit the call time limit, or null
     * @throws LimitPassed if the call passed its limit
     * @throws Exception   what the primitive threw
     */
    public static <T> T run(MissionClock clock, Duration limit, ExecutorService threads, Callable<T> call)
            throws Exception {
        PrimitiveTurn turn = PrimitiveTurn.current();
        long deadline = limit == null ? Long.MAX_VALUE : clock.millis() + limit.toMillis();
        ClockedCall clocked = new ClockedCall(clock, turn, deadline);
        if (turn == null && limit != null) {
            return clocked.onAnotherThread(threads, call);
        }
        if (turn != null) {
            turn.calling(clocked);
        }
        try {
            return clocked.within(call);
        } finally {
            clocked.finished = true;
            if (turn != null) {
                turn.calling(null);
            }
        }
    }

    private <T> T within(Callable<T> call) throws Exception {
        CURRENT.set(this);
        try {
            T value = call.call();
            if (passed) {
                throw new LimitPassed();
            }
            return value;
        } catch (InterruptedException interrupted) {
            if (passed) {
                throw new LimitPassed();
            }
            throw interrupted;
        } finally {
            CURRENT.remove();
            if (passed) {
                // The interruption that gave the primitive up is spent: the thread goes on with the mission.
                Thread.interrupted();
            }
        }
    }

    /** Held under a limit: the primitive runs on another thread, given up once it is blocked without end. */
    private <T> T onAnotherThread(ExecutorService threads, Callable<T> call) throws Exception {
        AtomicReference<Thread> runner = new AtomicReference<>();
        Future<T> running = threads.submit(() -> {
            runner.set(Thread.currentThread());
            return within(call);
        });
        while (!running.isDone()) {
            if (PrimitiveTurn.blockedWithoutEnd(runner.get()) && !running.isDone()) {
                passed = true;
                clock.passHeld(deadline);
                running.cancel(true);
                throw new LimitPassed();
            }
            LockSupport.parkNanos(this, LOOK_PERIOD_NANOS);
        }
        try {
            return running.get();
        } catch (ExecutionException failed) {
            if (failed.getCause() instanceof Error error) {
                throw error;
            }
            throw (Exception) failed.getCause();
        } finally {
            finished = true;
        }
    }

    /**
     * Sleeps {@code ms} milliseconds of mission time if the current thread runs a primitive on a
     * mission clock.
     *
     * @return false if it does not: the caller sleeps for real
     * @throws InterruptedException if the sleep reached the call's limit, or the mission ended
     */
    public static boolean sleep(long ms) throws InterruptedException {
        ClockedCall clocked = CURRENT.get();
        if (clocked == null) {
            return false;
        }
        clocked.sleepFor(ms);
        return true;
    }

    private void sleepFor(long ms) throws InterruptedException {
        if (passed || Thread.interrupted()) {
            throw new InterruptedException();
        }
        if (ms <= 0) {
            return;
        }
        long now = clock.millis();
        boolean pastLimit = ms > deadline - now;
        long until = pastLimit ? deadline : now + ms;
        if (turn != null) {
            turn.sleepUntil(clock, until);
        } else {
            clock.passHeld(until);
        }
        if (pastLimit) {
            passed = true;
            throw new InterruptedException("past the call time limit");
        }
    }

    /** The body is blocked without end and its turn is over: it is interrupted when the clock reaches the limit. */
    void giveUpAtDeadline(PrimitiveTurn blocked) {
        if (deadline == Long.MAX_VALUE || passed) {
            // Without a limit it waits as long as it must; once given up, the interruption is all there is.
            return;
        }
        clock.runAt(deadline, () -> {
            if (!finished) {
                passed = true;
                blocked.interruptBody();
            }
        });
    }

    /** The call passed its time limit on the mission clock: its caller gets the default value and {@code timeout}. */
    public static final class LimitPassed extends Exception {
        private static final long serialVersionUID = 1L;

        LimitPassed() {
            super(null, null, false, false);
        }
    }
}
