package masl.runtime.invocation;

import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import masl.runtime.scheduling.Blocking;
import masl.runtime.scheduling.ClockedCall;
import masl.runtime.scheduling.MissionClock;
import masl.runtime.scheduling.PrimitiveTurn;
import masl.runtime.scheduling.Scheduler;

/**
 * How a mission runs its primitives' Java code: within its call timeout if it has one, and on the
 * threads of its own that asynchronous primitives and timed calls run on. Owns those threads.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class PrimitiveCalls {

    private final Scheduler scheduler;
    /** How long a primitive may run before its caller gets {@code timeout}; null: no limit. */
    private final Duration callTimeout;
    private final ExecutorService threads = Executors.newCachedThreadPool(runnable -> {
        Thread thread = new Thread(runnable, "masl-primitive");
        thread.setDaemon(true);
        return thread;
    });

    public PrimitiveCalls(Scheduler scheduler, Duration callTimeout) {
        this.scheduler = scheduler;
        this.callTimeout = callTimeout;
    }

    /** The threads primitives run on when the scheduler does not order them ({@link Scheduler#runPrimitive}). */
    public ExecutorService threads() {
        return threads;
    }

    /** The mission is over: a primitive still running is interrupted, one submitted now is refused. */
    public void shutdownNow() {
        threads.shutdownNow();
    }

    /**
     * Runs a primitive's Java code for a caller, within the mission's call timeout if it has one: then
     * on a thread of its own, the caller's blocking wait letting the pool go on ({@link Blocking}).
     * The timeout counts from the moment the primitive starts on that thread: it bounds how long the
     * primitive runs, so a loaded machine that is slow to start the thread does not turn a quick
     * primitive into a {@code timeout}. On a scheduler that keeps the mission's time, sleeps and
     * the timeout are counted on its clock instead ({@link ClockedCall}).
     *
     * @throws TimedOut if it ran past the timeout: its thread is interrupted, its result dropped
     * @throws Exception what the primitive threw
     */
    public <T> T call(Callable<T> call) throws Exception {
        if (scheduler instanceof MissionClock clock) {
            try {
                return ClockedCall.run(clock, callTimeout, threads, call);
            } catch (ClockedCall.LimitPassed late) {
                throw new TimedOut();
            }
        }
        if (callTimeout == null) {
            return call.call();
        }
        CountDownLatch started = new CountDownLatch(1);
        PrimitiveTurn turn = PrimitiveTurn.current();
        if (turn != null) {
            turn.delegating();
        }
        Future<T> running = threads.submit(() -> {
            if (turn != null) {
                turn.delegateStarted();
            }
            try {
                started.countDown();
                return call.call();
            } finally {
                if (turn != null) {
                    turn.delegateFinished();
                }
            }
        });
        try {
            return Blocking.call(() -> {
                started.await();
                return running.get(callTimeout.toNanos(), TimeUnit.NANOSECONDS);
            });
        } catch (TimeoutException late) {
            running.cancel(true);
            throw new TimedOut();
        } catch (ExecutionException failed) {
            if (failed.getCause() instanceof Error error) {
                throw error;
            }
            throw (Exception) failed.getCause();
        } finally {
            if (turn != null) {
                turn.delegationEnded();
            }
        }
    }

    /** A primitive ran past the mission's call timeout. */
    public static final class TimedOut extends Exception {
        private static final long serialVersionUID = 1L;

        TimedOut() {
            super(null, null, false, false);
        }
    }
}
