package masl.cli;

import java.io.PrintStream;
import java.time.Duration;

/**
 * Ends the JVM with the command's status, and ends it even if a shutdown hook hangs. JADE 4.3's AMS
 * registers one that shuts its platform down at the JVM's exit; when the platform failed to shut
 * down (a row of the AMS's agent table left locked, which masl reports as the platform not closing),
 * that hook waits on the row forever, and {@code System.exit} with it: the command would never end.
 * A daemon thread started just before the exit halts the JVM, with the same status, once the hooks
 * have had {@link #HOOKS_WITHIN}.
 */
final class ExitGuard {

    /** How long the JVM's shutdown hooks may take: JADE's shutdown of a live platform takes 3–4 s. */
    static final Duration HOOKS_WITHIN = Duration.ofSeconds(15);

    private ExitGuard() {
    }

    /** {@code System.exit(status)}, halting with {@code status} if the hooks take longer than {@link #HOOKS_WITHIN}. */
    static void exit(int status) {
        exit(status, HOOKS_WITHIN, System.err);
    }

    static void exit(int status, Duration hooksWithin, PrintStream err) {
        Thread guard = new Thread(() -> {
            try {
                Thread.sleep(hooksWithin.toMillis());
            } catch (InterruptedException notToHalt) {
                return;
            }
            err.println("masl: the JVM's shutdown hooks did not end within " + hooksWithin.toSeconds()
                    + " s (JADE's, after its platform failed to shut down): halting");
            err.flush();
            System.out.flush();
            Runtime.getRuntime().halt(status);
        }, "masl-exit-guard");
        guard.setDaemon(true);
        guard.start();
        System.exit(status);
    }
}
