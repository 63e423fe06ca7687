package masl.cli;

import java.io.PrintStream;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;

/**
 * Ctrl-C (SIGINT) and SIGTERM during {@code masl run}. The JVM answers them by running its shutdown
 * hooks and then halting with status 128 + the signal's number (130, 143), whatever its other
 * threads are doing. This hook stops the mission and then waits, at most {@link #GRACE}, for the
 * command to finish the run as after any other end: the trace's {@code mission-ended} record (with
 * {@link #REASON}) written and the file closed, the journal flushed, one line on standard error.
 * A signal before the mission exists prints that line itself; the run then stops where it is.
 */
final class StopOnSignal implements AutoCloseable {

    /** Why the mission stopped, as its {@code mission-ended} record and standard error say. */
    static final String REASON = "a signal: Ctrl-C (SIGINT) or SIGTERM";
    /** Stopping, writing the last record and closing the files take milliseconds; a stuck run is not waited for. */
    static final Duration GRACE = Duration.ofSeconds(10);

    private final PrintStream err;
    private final Thread hook = new Thread(this::stopAndWait, "masl-signal");
    private final CountDownLatch finished = new CountDownLatch(1);
    private Consumer<String> stop;
    private boolean signalled;

    StopOnSignal(PrintStream err) {
        this.err = err;
        Runtime.getRuntime().addShutdownHook(hook);
    }

    /**
     * The mission a signal stops from now on, by {@code stop} (given {@link #REASON}).
     *
     * @return false if a signal came first: the JVM is halting, the mission must not start
     */
    synchronized boolean stops(Consumer<String> stop) {
        this.stop = stop;
        return !signalled;
    }

    /** Whether a signal stopped the mission: then standard error says so, in one line. */
    synchronized boolean signalled() {
        return signalled;
    }

    private void stopAndWait() {
        Consumer<String> mission;
        synchronized (this) {
            signalled = true;
            mission = stop;
        }
        if (mission == null) {
            err.println("masl: stopped by " + REASON + " before the mission started");
            return;
        }
        mission.accept(REASON);
        try {
            finished.await(GRACE.toMillis(), TimeUnit.MILLISECONDS);
        } catch (InterruptedException halting) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * The run is over and reported: a signal from now on is the JVM's alone. If a signal came, never
     * returns: the JVM is halting with the signal's status.
     */
    @Override
    public void close() {
        finished.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // A signal came: the hook is running and has just been released. Once it returns, the JVM
            // halts with the signal's status (130, 143); a System.exit with the run's own status,
            // made in the instant between the hooks' end and that halt, would halt it first (seen
            // once: status 2 after SIGTERM). So this thread waits for the halt.
            awaitHalt();
        }
    }

    private static void awaitHalt() {
        while (true) {
            LockSupport.park();
        }
    }
}
