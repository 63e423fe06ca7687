package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.File;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.stream.Collectors;
import masl.e2e.agents.HomeOnly;
import masl.jade.trust.MissionSecret;
import masl.jade.trust.SecretFile;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code masl run} on the project's own missions, as the README shows it, and as a process a user stops. */
@Timeout(180)
@Tag("slow")
class CommandLineTest {

    @TempDir
    Path folder;

    @Test
    void helloPrintsOneGreetingFromOneOfItsThreeAgents() {
        MaslCommand run = MaslCommand.run("run", "missions/hello.masl");
        assertEquals(0, run.status(), run.err());
        assertTrue(run.out().matches("Hello from agent [012]\n"), run.out());
        assertEquals("", run.err());
    }

    /**
     * SIGTERM (what {@code Process.destroy()} sends, and {@code kill}) or Ctrl-C while the mission
     * runs: the trace is flushed and closed, its last line a whole {@code mission-ended} record
     * saying why, one line on standard error, status 128 + 15.
     */
    @Test
    void sigtermEndsTheTraceWithMissionEndedAndPrintsOneLine() throws Exception {
        Path program = folder.resolve("ticking.masl");
        Files.writeString(program, """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                asynchronous entry main (true) {
                  asynchronous entry tick (true) {
                    .nop();
                    reelect;
                  }
                }
                """);
        Path trace = folder.resolve("trace.jsonl");
        try (MaslProcess masl = MaslProcess.start(folder.resolve("journal.txt").toFile(), "run", program.toString(),
                "--trace", trace.toString(), "--quiet")) {
            awaitRecords(trace, masl);
            masl.terminate();
            assertEquals(143, masl.awaitExit(), masl::toString);
            assertEquals("masl: the mission was stopped by a signal: Ctrl-C (SIGINT) or SIGTERM\n", masl.err());
        }
        JsonNode last = CompleteTrace.lastRecord(trace);
        assertEquals("mission-ended", last.get("event").asText(), last::toString);
        assertEquals("stopped", last.get("status").asText(), last::toString);
        assertEquals("a signal: Ctrl-C (SIGINT) or SIGTERM", last.get("reason").asText(), last::toString);
    }

    /** {@code masl run hello.masl > /dev/full}: the journal is lost, so the run fails and says so. */
    @Test
    void aJournalThatCannotBeWrittenFailsTheRun() throws Exception {
        File full = new File("/dev/full");
        assertTrue(full.exists(), "this test needs Linux's /dev/full");
        try (MaslProcess masl = MaslProcess.start(full, "run", "missions/hello.masl", "--quiet")) {
            assertEquals(2, masl.awaitExit(), masl::toString);
            assertEquals("masl: cannot write the journal to standard output\n", masl.err());
        }
    }

    /** {@code masl run p.masl >> p.masl}: the journal would be written into the program, which is kept. */
    @Test
    void aJournalAppendedToTheProgramIsRefused() throws Exception {
        Path program = Files.writeString(folder.resolve("victim.masl"), """
                import Default.xml as Default;
                Default a = newAgent(Default);
                scalar entry main (true) { .logln("hi"); }
                """);
        String text = Files.readString(program);
        try (MaslProcess masl = MaslProcess.startAppendingTo(program.toFile(), "run", program.toString(), "--quiet")) {
            assertEquals(64, masl.awaitExit(), masl::toString);
            assertTrue(masl.err().startsWith("masl: the journal (standard output) /dev/stdout is the program " + program
                    + " (the same file): masl does not write over a file it reads\n"), masl::toString);
        }
        assertEquals(text, Files.readString(program));
    }

    /** JADE prints the stack traces of a failed join on standard error: the user sees one line instead. */
    @Test
    void joiningAPlatformWhoseMainContainerIsNotThereIsOneLine() throws Exception {
        int port = freePort();
        try (MaslProcess masl = MaslProcess.start(folder.resolve("journal.txt").toFile(), "run", "missions/hello.masl", "--quiet",
                "--platform", "jade", "--main-host", "127.0.0.1", "--main-port", String.valueOf(port))) {
            assertEquals(2, masl.awaitExit(), masl::toString);
            assertEquals("masl: cannot join the JADE platform at 127.0.0.1:" + port + " (is its main container running?)\n",
                    masl.err());
        }
    }

    /**
     * A serving container whose mission's secret is there but whose platform does not answer says
     * so at once, once, while it keeps trying; then, at its timeout, that it could not join.
     */
    @Test
    void aServingContainerThatCannotJoinItsMissionsPlatformSaysSoOnceWhileItTries() throws Exception {
        int port = freePort();
        Path secret = folder.resolve("secret");
        try (SecretFile written = MissionSecret.generate().writeTo(secret);
                MaslProcess container = MaslProcess.start(folder.resolve("container.txt").toFile(), "container", "--serve",
                        "--main-host", "127.0.0.1", "--main-port", String.valueOf(port), "--name", "c9", "--timeout", "3",
                        "--secret-file", secret.toString())) {
            assertEquals(2, container.awaitExit(), container::toString);
            String cannot = "masl: container c9: cannot join the JADE platform at 127.0.0.1:" + port
                    + " (is its main container running?)";
            assertEquals(cannot + "; trying again until the mission's timeout\n" + cannot + "\n", container.err());
        }
    }

    /**
     * {@code masl container} on a host where the class of the agent placed there cannot be
     * initialised: each side says so in one line, what the class threw included, with status 2.
     */
    @Test
    void aContainerThatCannotHostItsAgentIsOneLineOnEachSide() throws Exception {
        String port = String.valueOf(freePort());
        String secret = folder.resolve("secret").toString();
        String why = "masl: container c2 cannot host b: class masl.e2e.agents.HomeOnly: its static initialiser threw"
                + " java.lang.IllegalStateException: no robot on this host\n";
        try (MaslProcess container = MaslProcess.start(Map.of(HomeOnly.NO_ROBOT, "yes"),
                folder.resolve("container.txt").toFile(), "container", "--main-host", "127.0.0.1", "--main-port", port,
                "--name", "c2", "--agent-path", "src/test/resources/faults/agents", "--timeout", "60",
                "--secret-file", secret);
                MaslProcess run = MaslProcess.start(folder.resolve("journal.txt").toFile(), "run",
                        "src/test/resources/faults/home_only.masl", "--quiet", "--platform", "jade", "--port", port, "--place", "b=c2",
                        "--timeout", "60", "--secret-file", secret)) {
            assertEquals(2, run.awaitExit(), run::toString);
            assertEquals("masl: platform ready: host=127.0.0.1 port=" + port + " platform=127.0.0.1:" + port + "/JADE\n"
                    + why, maslLines(run.err()));
            // The container's end may race the platform's: JADE then says so too (a stack trace folded to one
            // line, a warning), on either side.
            assertTrue(run.err().lines().noneMatch(line -> line.startsWith("\tat ")), run::toString);
            assertEquals(2, container.awaitExit(), container::toString);
            assertEquals(why, maslLines(container.err()));
        }
    }

    /** The lines masl wrote, without any JADE wrote on the same standard error. */
    private static String maslLines(String err) {
        return err.lines().filter(line -> line.startsWith("masl: ")).map(line -> line + "\n").collect(Collectors.joining());
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }

    /** Waits until the trace file has records on disk: the mission runs (the writer flushes its buffer as it fills). */
    private static void awaitRecords(Path trace, MaslProcess masl) throws IOException, InterruptedException {
        long deadline = System.nanoTime() + 120_000_000_000L;
        while (!Files.exists(trace) || Files.size(trace) == 0) {
            if (!masl.process().isAlive() || System.nanoTime() - deadline > 0) {
                throw new AssertionError("no trace records from the running mission: " + masl.err());
            }
            Thread.sleep(50);
        }
    }
}
