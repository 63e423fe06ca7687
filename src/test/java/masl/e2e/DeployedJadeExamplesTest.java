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
import masl.cli.Main;
import masl.jade.platform.JadeThreads;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Examples of examples.md from their MASL sources, every agent's program deployed over two containers
 * in two other JVMs ({@code masl container --name c2}, {@code c3}), as a user runs them:
 * {@code masl run --platform jade --deploy '*=c2+c3'} in this JVM keeps the mission (blocks, barriers,
 * shared variables, events, the journal), each container translates the program it is sent and runs
 * its agents' steps. Journals as in-process; each container ends by itself with the mission.
 */
@Timeout(300)
@Tag("slow")
class DeployedJadeExamplesTest {

    /**
     * Lock-step with shared variables, an event reacted to in the parent, and an invocation denied by
     * the callee's state in the other container; the other examples run deployed in the bridge's tests
     * (DeployedExamplesTest, over in-memory wires), each JVM here costing seconds.
     */
    @Test
    void e2E4AndE5() throws Exception {
        assertEquals("n=5\n" + "mine=1\n".repeat(5), deployed("e2_shared_and_local.masl").journal());
        List<String> e4 = deployed("e4_events.masl").journal().lines().toList();
        assertEquals(List.of("heard now", "heard now", "heard now", "heard now", "worker 1", "worker 2", "worker 3"),
                e4.stream().sorted().toList());
        assertEquals("heard now", e4.get(0));
        Run e5 = deployed("e5_permeability.masl");
        assertEquals("timeout\nseen=0\n", e5.journal());
        assertTrue(e5.c2().lines().anyMatch(line -> line.startsWith("masl: container ready: name=c2 ")
                && line.endsWith(" agents=a")), e5.c2());
        assertTrue(e5.c3().contains("masl-ended hosted b"), e5.c3());
    }

    /** The manual's labels (§10): an {@code SLabel} the agent running main waits on, one robot in each container. */
    @Test
    void labels(@TempDir Path folder) throws Exception {
        Path program = Files.writeString(folder.resolve("calibrate.masl"), DeployedLabelsTest.CALIBRATE);
        assertEquals("both calibrated: true\n", deployed(program).journal());
    }

    private record Run(String journal, String c2, String c3) {
    }

    private static Run deployed(String example) throws Exception {
        return deployed(Path.of("src/test/resources/examples", example));
    }

    private static Run deployed(Path program) throws Exception {
        int port = freePort();
        Path secretFile = Files.createTempDirectory("masl-mission").resolve("secret");
        try (SecondJvm c2 = container(port, "c2", secretFile); SecondJvm c3 = container(port, "c3", secretFile)) {
            MaslCommand run = MaslCommand.run("run", program.toString(), "--platform", "jade",
                    "--port", String.valueOf(port), "--deploy", "*=c2+c3", "--timeout", "120",
                    "--secret-file", secretFile.toString());
            assertEquals("masl: platform ready: host=127.0.0.1 port=" + port + " platform=127.0.0.1:" + port + "/JADE\n",
                    run.err(), c2.output() + c3.output());
            assertEquals(0, run.status(), c2.output() + c3.output());
            assertEquals(List.of(), JadeThreads.live(), "JADE threads left in this JVM after the mission");
            assertFalse(Files.exists(secretFile), "the mission's secret outlived it");
            return new Run(run.out(), c2.assertEndsByItself(), c3.assertEndsByItself());
        } finally {
            Files.deleteIfExists(secretFile);
            Files.delete(secretFile.getParent());
        }
    }

    private static SecondJvm container(int port, String name, Path secretFile) throws IOException {
        return SecondJvm.start(Main.class, "container", "--main-host", "127.0.0.1", "--main-port", String.valueOf(port),
                "--name", name, "--timeout", "180", "--secret-file", secretFile.toString());
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }
}
