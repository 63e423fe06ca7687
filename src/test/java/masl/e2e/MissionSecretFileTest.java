package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.stream.Stream;
import masl.jade.platform.Readiness;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Two missions run with {@code --place} from one folder, each with the default secret file: the end
 * of one leaves the other's secret, so the other's container, started after, is still placed, and no
 * secret file is left. Child JVMs in the folder: {@code masl run} twice, {@code masl container} for each.
 */
@Timeout(180)
@Tag("slow")
class MissionSecretFileTest {

    private static final Duration WITHIN = Duration.ofSeconds(60);
    private static final String PROGRAM = Path.of("src/test/resources/examples/e2_shared_and_local.masl")
            .toAbsolutePath().toString();

    @TempDir
    Path folder;

    @Test
    void twoMissionsInOneFolderKeepTheirOwnSecrets() throws Exception {
        try (MaslProcess first = run("first"); MaslProcess second = run("second")) {
            int firstPort = port(first);
            int secondPort = port(second);
            try (MaslProcess container = container(secondPort, "second")) {
                assertEquals(0, container.awaitExit(), container.toString());
            }
            assertEquals(0, second.awaitExit(), second.toString());
            try (MaslProcess container = container(firstPort, "first")) {
                assertEquals(0, container.awaitExit(), container.toString());
            }
            assertEquals(0, first.awaitExit(), first.toString());
            assertEquals("n=5\n" + "mine=1\n".repeat(5), Files.readString(folder.resolve("first.journal")));
        }
        try (Stream<Path> left = Files.list(folder)) {
            assertTrue(left.noneMatch(file -> file.getFileName().toString().startsWith(".masl")),
                    "a secret file outlived its mission");
        }
    }

    private MaslProcess run(String name) throws Exception {
        return MaslProcess.startIn(folder, folder.resolve(name + ".journal").toFile(), "run", PROGRAM, "--quiet",
                "--platform", "jade", "--place", "b=c2,d=c2", "--timeout", "90");
    }

    private MaslProcess container(int port, String name) throws Exception {
        return MaslProcess.startIn(folder, folder.resolve(name + ".container").toFile(), "container", "--main-host",
                "127.0.0.1", "--main-port", String.valueOf(port), "--name", "c2", "--timeout", "60");
    }

    private static int port(MaslProcess run) throws InterruptedException {
        Optional<Readiness> ready = run.awaitErrLine(Readiness::parse, WITHIN);
        assertTrue(ready.isPresent(), run.toString());
        return ready.get().port();
    }
}
