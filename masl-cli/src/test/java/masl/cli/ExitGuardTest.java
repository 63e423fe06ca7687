package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A command whose JVM has a shutdown hook that never returns (JADE's AMS, after its platform failed
 * to shut down) still ends, with its own status, and says why: run in a JVM of its own.
 */
class ExitGuardTest {

    @TempDir
    Path folder;

    @Test
    void aHangingShutdownHookDoesNotKeepTheCommandFromEnding() throws Exception {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Path errFile = folder.resolve("err.txt");
        Process process = new ProcessBuilder(java.toString(), "-cp", System.getProperty("java.class.path"),
                HangingHook.class.getName()).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .redirectError(errFile.toFile()).start();
        boolean ended = process.waitFor(30, TimeUnit.SECONDS);
        if (!ended) {
            process.destroyForcibly().waitFor();
        }
        assertTrue(ended, "the JVM ended");
        String err = Files.readString(errFile);
        assertEquals(3, process.exitValue(), err);
        assertEquals("masl: the JVM's shutdown hooks did not end within 1 s (JADE's, after its platform failed to"
                + " shut down): halting\n", err);
    }

    /** A JVM whose one shutdown hook waits forever, ended with status 3 through the guard. */
    public static final class HangingHook {

        public static void main(String[] args) {
            Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                try {
                    new CountDownLatch(1).await();
                } catch (InterruptedException ignored) {
                    Thread.currentThread().interrupt();
                }
            }));
            ExitGuard.exit(3, Duration.ofSeconds(1), System.err);
        }
    }
}
