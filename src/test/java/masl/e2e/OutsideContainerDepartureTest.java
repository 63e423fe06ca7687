package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import masl.jade.platform.Readiness;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A plain JADE container (outside agents' own, not {@code masl container}) joins the platform of
 * {@code masl run --platform jade} from another JVM and is killed: the coordinator says so in one line
 * of its own, not in JADE's words ({@code EOF reached}, {@code Node <c9> UNREACHABLE}), and prints no
 * stack trace.
 */
@Timeout(180)
@Tag("slow")
class OutsideContainerDepartureTest {

    private static final Duration WITHIN = Duration.ofSeconds(90);

    @TempDir
    Path folder;

    @Test
    void aKilledOutsideContainerIsOneLineOfTheCoordinators() throws Exception {
        Path program = Files.writeString(folder.resolve("idle.masl"), """
                import Default.xml as Default;
                Default a = newAgent(Default);
                asynchronous entry main (true) { while (true) { .sleep(100); } }
                """);
        try (MaslProcess run = MaslProcess.start(folder.resolve("journal.txt").toFile(), "run", program.toString(),
                "--quiet", "--platform", "jade", "--timeout", "170")) {
            Optional<Readiness> platform = run.awaitErrLine(Readiness::parse, WITHIN);
            assertTrue(platform.isPresent(), run.toString());
            Path containerLog = folder.resolve("c9.txt");
            Process outside = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", System.getProperty("java.class.path"), "jade.Boot", "-container", "-container-name", "c9",
                    "-host", platform.get().host(), "-port", String.valueOf(platform.get().port()),
                    "-local-host", "127.0.0.1", "-local-port", String.valueOf(freePort()))
                    .redirectErrorStream(true).redirectOutput(containerLog.toFile()).start();
            try {
                awaitJoined(outside, containerLog);
                outside.destroyForcibly();
                assertTrue(outside.waitFor(30, TimeUnit.SECONDS));
                Optional<String> departure = run.awaitErrLine(line -> Optional.of(line).filter(said -> said.contains("c9")),
                        WITHIN);
                assertEquals(Optional.of("masl: container c9 left the platform (its JVM ended or its connection broke)"),
                        departure, run.toString());
            } finally {
                outside.destroyForcibly();
            }
            run.terminate();
            assertEquals(143, run.awaitExit(), run.toString());
            String err = run.err();
            assertEquals(1, err.lines().filter(line -> line.contains("c9")).count(), err);
            assertFalse(err.contains("EOF reached"), err);
            assertFalse(err.contains("UNREACHABLE"), err);
            assertFalse(err.contains("NotFoundException"), err);
            assertFalse(err.contains("\tat "), err);
        }
    }

    /** JADE's container says, in its log, that it is ready once it has joined. */
    private static void awaitJoined(Process outside, Path log) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + WITHIN.toNanos();
        while (!Files.readString(log).contains("Agent container c9@")) {
            assertTrue(outside.isAlive(), () -> "the JADE container ended: " + read(log));
            assertTrue(System.nanoTime() < deadline, () -> "the JADE container did not join: " + read(log));
            Thread.sleep(100);
        }
    }

    private static String read(Path log) {
        try {
            return Files.readString(log);
        } catch (IOException unreadable) {
            return unreadable.toString();
        }
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }
}
