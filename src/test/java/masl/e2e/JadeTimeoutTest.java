package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Optional;
import java.util.stream.Collectors;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code masl run --platform jade --timeout} with agents that never park: one polls its own type's
 * accessor in an empty {@code while}, one is inside a primitive that outlasts the mission. The run
 * ends on its timeout with the report of an in-process run, status 2, and no JADE thread left (JADE's
 * shutdown would say which were), with every agent here and with their bodies in another JVM.
 */
@Timeout(180)
class JadeTimeoutTest {

    private static final String PROGRAM = "src/test/resources/jade_timeout/stuck.masl";
    private static final String AGENTS = "src/test/resources/jade_timeout/agents";
    private static final String TIMEOUT_SECONDS = "4";
    /**
     * From the moment the mission can start to the end of the run: the timeout and a generous margin
     * for a loaded machine. A driver that does not see the mission's end keeps the run some 40 s longer.
     */
    private static final Duration BOUND = Duration.ofSeconds(25);

    /** What {@code masl run --timeout} of the same program says in-process: what each run in JADE must say. */
    private static String inProcess;

    @TempDir
    Path folder;

    @BeforeAll
    static void runInProcess(@TempDir Path inProcessFolder) throws Exception {
        inProcess = inProcessReport(inProcessFolder);
    }

    @Test
    void aRunWhoseAgentsNeverParkEndsOnItsTimeoutWithTheReportOfAnInProcessRun() throws Exception {
        try (MaslProcess run = MaslProcess.start(folder.resolve("journal.txt").toFile(), "run", PROGRAM, "--quiet",
                "--platform", "jade", "--timeout", TIMEOUT_SECONDS)) {
            long ready = awaitLine(run, "masl: platform ready: ");
            assertEquals(2, run.awaitExit(), run::toString);
            assertEndedWithin(ready, run);
            assertEquals(inProcess, withoutReadiness(run.err()), run::toString);
        }
    }

    @Test
    void aRunWhoseAgentsBodiesAreInAnotherJvmEndsOnItsTimeoutAndSoDoesTheirContainer() throws Exception {
        String port = String.valueOf(freePort());
        String secret = folder.resolve("secret").toString();
        try (MaslProcess container = MaslProcess.start(folder.resolve("container.txt").toFile(), "container",
                "--main-host", "127.0.0.1", "--main-port", port, "--name", "c2", "--agent-path", AGENTS,
                "--timeout", "120", "--secret-file", secret);
                MaslProcess run = MaslProcess.start(folder.resolve("journal.txt").toFile(), "run", PROGRAM, "--quiet",
                        "--platform", "jade", "--port", port, "--place", "a=c2,b=c2", "--timeout", TIMEOUT_SECONDS,
                        "--secret-file", secret)) {
            long hosting = awaitLine(container, "masl: container ready: ");
            assertEquals(2, run.awaitExit(), run::toString);
            assertEndedWithin(hosting, run);
            assertEquals(inProcess, withoutReadiness(run.err()), run::toString);
            assertEquals(0, container.awaitExit(), container::toString);
            assertEquals(Optional.of("masl-ended hosted a,b"),
                    Files.readAllLines(folder.resolve("container.txt")).stream()
                            .filter(line -> line.startsWith("masl-ended")).findFirst());
            assertEquals("", maslLines(container.err()).replaceFirst("masl: container ready: [^\n]*\n", ""),
                    container::toString);
        }
    }

    /** What {@code masl run --timeout} of the same program says in-process. */
    private static String inProcessReport(Path folder) throws Exception {
        try (MaslProcess run = MaslProcess.start(folder.resolve("in-process.txt").toFile(), "run", PROGRAM, "--quiet",
                "--timeout", TIMEOUT_SECONDS)) {
            assertEquals(2, run.awaitExit(), run::toString);
            String report = run.err();
            assertTrue(report.startsWith("masl: the mission timed out\nagent a (0) at pc "), report);
            assertTrue(report.contains("(stuck.masl:6: while (!.opened())): [main]\n"), report);
            assertTrue(report.contains("(stuck.masl:9: .holdFor(60000);): [main]\n"), report);
            return report;
        }
    }

    /** When the first line of its standard error starting with {@code prefix} came ({@link System#nanoTime()}). */
    private static long awaitLine(MaslProcess masl, String prefix) throws InterruptedException {
        Optional<String> line = masl.awaitErrLine(read -> Optional.of(read).filter(text -> text.startsWith(prefix)),
                Duration.ofSeconds(120));
        assertTrue(line.isPresent(), () -> "no line " + prefix + "… on " + masl);
        return System.nanoTime();
    }

    private static void assertEndedWithin(long since, MaslProcess run) {
        Duration took = Duration.ofNanos(System.nanoTime() - since);
        assertTrue(took.compareTo(BOUND) < 0, () -> "the run ended " + took + " after it could start the mission, "
                + "with a timeout of " + TIMEOUT_SECONDS + " s; " + run);
    }

    /** The lines masl wrote but the one saying where the platform is ready (JADE may write lines of its own). */
    private static String withoutReadiness(String err) {
        return err.lines().filter(line -> !line.startsWith("masl: platform ready: "))
                .filter(line -> line.startsWith("masl: ") || line.startsWith("agent "))
                .map(line -> line + "\n").collect(Collectors.joining());
    }

    private static String maslLines(String err) {
        return err.lines().filter(line -> line.startsWith("masl: ")).map(line -> line + "\n")
                .collect(Collectors.joining());
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }
}
