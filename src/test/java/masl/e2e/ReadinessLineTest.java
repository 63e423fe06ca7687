package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Optional;
import masl.jade.platform.Readiness;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Another JVM knows when and where to join without polling: {@code masl run --platform jade} (no
 * {@code --port}: a free one) runs in a child JVM; this JVM waits for its readiness line on standard
 * error, reads the address from it, and starts {@code masl container} in another child JVM joining
 * there, which says in turn, in one line, that it hosts its bodies. The mission (E2, two bodies placed
 * on the container) completes. No JADE runs in this JVM.
 */
@Timeout(120)
@Tag("slow")
class ReadinessLineTest {

    private static final Duration WITHIN = Duration.ofSeconds(60);

    @Test
    void aSecondJvmJoinsThePlatformAtTheAddressOfItsReadinessLine() throws Exception {
        Path secretFile = Files.createTempDirectory("masl-mission").resolve("secret");
        Path journal = secretFile.resolveSibling("journal.txt");
        Path containerOut = secretFile.resolveSibling("container.txt");
        try (MaslProcess run = MaslProcess.start(journal.toFile(), "run", "src/test/resources/examples/e2_shared_and_local.masl",
                "--quiet", "--platform", "jade", "--place", "b=c2,d=c2", "--timeout", "60", "--secret-file",
                secretFile.toString())) {
            Optional<Readiness> platform = run.awaitErrLine(Readiness::parse, WITHIN);
            assertTrue(platform.isPresent(), run.toString());
            assertEquals(Optional.empty(), platform.get().container());
            assertEquals("127.0.0.1", platform.get().host());
            assertTrue(platform.get().platform().endsWith(":" + platform.get().port() + "/JADE"), run.toString());

            try (MaslProcess container = MaslProcess.start(containerOut.toFile(), "container", "--main-host",
                    platform.get().host(), "--main-port", String.valueOf(platform.get().port()), "--name", "c2",
                    "--timeout", "60", "--secret-file", secretFile.toString())) {
                Optional<Readiness> placed = container.awaitErrLine(Readiness::parse, WITHIN);
                assertEquals(Optional.of(new Readiness(Optional.of("c2"), platform.get().host(), platform.get().port(),
                        platform.get().platform(), List.of("b", "d"))), placed, container.toString());
                assertEquals(0, container.awaitExit(), container.toString());
                assertEquals("masl-ended hosted b,d\n", Files.readString(containerOut));
            }
            assertEquals(0, run.awaitExit(), run.toString());
            assertEquals("n=5\n" + "mine=1\n".repeat(5), Files.readString(journal));
            assertEquals(List.of("masl: platform ready: host=127.0.0.1 port=" + platform.get().port() + " platform="
                    + platform.get().platform()), run.err().lines().toList());
        } finally {
            Files.deleteIfExists(secretFile);
            Files.deleteIfExists(journal);
            Files.deleteIfExists(containerOut);
            Files.delete(secretFile.getParent());
        }
    }
}
