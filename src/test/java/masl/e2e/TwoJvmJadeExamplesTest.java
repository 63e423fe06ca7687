package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import masl.cli.Main;
import masl.jade.platform.JadeThreads;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * E2, E4 and E6 of examples.md from their MASL sources, with their agents split across two
 * containers in two JVMs on loopback, as a user runs them: {@code masl container --name c2} in a
 * second JVM (started here with this class path and the {@code java} of {@code java.home}), and
 * {@code masl run --platform jade --port P --place …} in this one, which starts the main container,
 * runs every program and the coordinator, and has the bodies placed on {@code c2} run their
 * primitives there; the two share the mission's secret through a file ({@code --secret-file}), which
 * {@code masl run} deletes at the end. Journals as examples.md states them; the second JVM ends by itself when the
 * mission ends (and is ended in any case); no JADE thread is left in this JVM after each mission.
 */
@Timeout(120)
@Tag("slow")
class TwoJvmJadeExamplesTest {

    @Test
    void e2SharedAndLocalVariablesInLockStep() throws Exception {
        Run run = split("e2_shared_and_local.masl", "b=c2,d=c2");
        assertEquals("n=5\n" + "mine=1\n".repeat(5), run.journal());
        // JADE may log a warning of its own as the container closes, after masl's last line.
        List<String> container = run.containerOutput().lines().toList();
        assertTrue(container.contains("masl-ended hosted b,d"), run.containerOutput());
        assertTrue(container.stream().anyMatch(line -> line.startsWith("masl: container ready: name=c2 ")
                && line.endsWith(" agents=b,d")), run.containerOutput());
    }

    /** The leader and a worker away: the event `go` reaches their container as INFORM masl-event. */
    @Test
    void e4EventsAreReactedToInTheParentAndResume() throws Exception {
        Run run = split("e4_events.masl", "leader=c2,w2=c2");
        List<String> lines = run.journal().lines().toList();
        assertEquals(List.of("heard now", "heard now", "heard now", "heard now", "worker 1", "worker 2", "worker 3"),
                lines.stream().sorted().toList(), run.journal());
        assertEquals("heard now", lines.get(0));
        for (int worker = 1; worker <= 3; worker++) {
            assertTrue(lines.indexOf("worker " + worker) > lines.indexOf("heard now"), run.journal());
        }
        String event = "masl-event {\"event\":\"go\",\"block\":\"main\",\"emitter\":\"leader\",\"message\":\"now\"}\n";
        assertEquals(1, run.containerOutput().split(Pattern.quote(event), -1).length - 1,
                "the event once, for the container:\n" + run.containerOutput());
    }

    /** b, whose body is away, denies a's invocation: the coordinator decides, a perceives timeout. */
    @Test
    void e5DeniedInvocationOfAnAgentInAnotherJvmBecomesTimeout() throws Exception {
        Run run = split("e5_permeability.masl", "b=c2");
        assertEquals("timeout\nseen=0\n", run.journal());
    }

    @Test
    void e6LockedBlockAdmitsOneAgentPerWave() throws Exception {
        Run run = split("e6_one_at_a_time.masl", "keeper=c2,p2=c2");
        assertEquals("in 1\n".repeat(3), run.journal());
    }

    private record Run(String journal, String containerOutput) {
    }

    private static Run split(String example, String placement) throws Exception {
        int port = freePort();
        Path secretFile = Files.createTempDirectory("masl-mission").resolve("secret");
        try (SecondJvm container = SecondJvm.start(Main.class, "container", "--main-host", "127.0.0.1",
                "--main-port", String.valueOf(port), "--name", "c2", "--timeout", "60",
                "--secret-file", secretFile.toString())) {
            MaslCommand run = MaslCommand.run("run", "src/test/resources/examples/" + example, "--platform", "jade",
                    "--port", String.valueOf(port), "--place", placement, "--timeout", "60",
                    "--secret-file", secretFile.toString());
            assertEquals("masl: platform ready: host=127.0.0.1 port=" + port + " platform=127.0.0.1:" + port + "/JADE\n",
                    run.err(), container.output());
            assertEquals(0, run.status(), container.output());
            assertEquals(List.of(), JadeThreads.live(), "JADE threads left in this JVM after the mission");
            assertFalse(Files.exists(secretFile), "the mission's secret outlived it");
            return new Run(run.out(), container.assertEndsByItself());
        } finally {
            Files.deleteIfExists(secretFile);
            Files.delete(secretFile.getParent());
        }
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }
}
