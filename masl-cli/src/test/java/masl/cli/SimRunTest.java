package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code masl run --sim SCENARIO}: streams, exit statuses, the output folder. */
@Timeout(120)
class SimRunTest {

    private static final String FLOOR = """
            <xode version="1.0r23"><world><space>
              <geom name="floor"><plane a="0" b="0" c="1" d="0"/></geom>
            </space></world></xode>""";

    private static final String DRIVE = """
            import WheeledRobot.xml as WheeledRobot;
            WheeledRobot k = newAgent(WheeledRobot);
            scalar entry main (true) {
              .setSpeeds(5.0, 5.0);
              .sleep(1000);
              .stop();
              .logln("drove");
            }
            """;

    @TempDir
    Path folder;

    private Path scenario(String mission) throws IOException {
        Files.writeString(folder.resolve("floor.xode"), FLOOR);
        Files.writeString(folder.resolve("drive.masl"), mission);
        return Files.writeString(folder.resolve("drive.scenario.xml"), """
                <scenario name="drive">
                  <world file="floor.xode"/>
                  <agent name="k" model="wheeled"><pose x="0" y="0" heading="0"/></agent>
                  <mission file="drive.masl"/>
                </scenario>""");
    }

    /** A clock that moves a quarter of a second each time it is read: every run looks long. */
    private static Progress.Settings slowClock(boolean terminal) {
        java.util.concurrent.atomic.AtomicLong now = new java.util.concurrent.atomic.AtomicLong();
        return new Progress.Settings(() -> now.addAndGet(250_000_000L), java.time.Duration.ofSeconds(1),
                java.time.Duration.ofSeconds(5), terminal, false);
    }

    /** A clock that never moves: every run is shorter than a second. */
    private static final Progress.Settings FROZEN_CLOCK = new Progress.Settings(() -> 0L, java.time.Duration.ofSeconds(1),
            java.time.Duration.ofSeconds(5), false, false);

    @Test
    void aLongRunReportsSimulatedTimeRealTimeFactorFromItsSecondLineAndJournalOnStandardErrorOnly() throws IOException {
        Run run = Run.with(slowClock(false), "run", "--sim", scenario(DRIVE).toString());

        assertEquals(0, run.status(), run.err());
        assertEquals("drove\n", run.out(), "the journal alone on standard output");
        List<String> lines = run.err().lines().filter(line -> line.startsWith("masl: simulated")).toList();
        assertTrue(lines.size() >= 2, "a line every few seconds: " + run.err());
        // The first line comes after the scenario was loaded and its worlds built: no rate of simulation yet.
        assertTrue(lines.get(0).matches("masl: simulated \\d+\\.\\d s, journal 0 lines"), lines.get(0));
        assertTrue(lines.get(1).matches("masl: simulated \\d+\\.\\d s, \\d+\\.\\d\\dx real time, journal [01] lines?"), lines.get(1));
        assertTrue(lines.get(lines.size() - 1).endsWith("journal 1 line") || lines.get(lines.size() - 1).endsWith("journal 0 lines"),
                lines.toString());
    }

    @Test
    void onATerminalTheLineIsRewrittenInPlaceAndErasedAtTheEnd() throws IOException {
        Run run = Run.with(slowClock(true), "run", "--sim", scenario(DRIVE).toString());

        assertEquals(0, run.status(), run.err());
        assertEquals("drove\n", run.out());
        assertTrue(run.err().contains("\rmasl: simulated"), run.err());
        int erased = run.err().lastIndexOf("\r\033[K");
        assertTrue(run.err().substring(erased + 4).matches("masl: [0-9.]+ s simulated; output in .*\n"),
                "the line is erased before the run's summary: " + run.err());
        assertFalse(run.err().substring(0, erased).contains("\n"), "one line, rewritten: " + run.err());
    }

    @Test
    void quietOrShortRunsShowNoProgress() throws IOException {
        Path scenario = scenario(DRIVE);
        Run quiet = Run.with(slowClock(false), "run", "--sim", scenario.toString(), "--quiet");
        Run shortRun = Run.with(FROZEN_CLOCK, "run", "--sim", scenario.toString());

        for (Run run : List.of(quiet, shortRun)) {
            assertEquals(0, run.status(), run.err());
            assertEquals("drove\n", run.out());
            assertEquals(1, run.err().lines().count(), run.err());
            assertTrue(run.err().matches("masl: [0-9.]+ s simulated; output in .*\n"), run.err());
        }
    }

    @Test
    void theSimulationsTraceIsCutAtItsLimit() throws IOException {
        Path scenario = scenario(TraceOutputTest.ticking("WheeledRobot", 300));

        Run run = Run.of("run", "--sim", scenario.toString(), "--trace-limit", "4K");

        assertEquals(0, run.status(), run.err());
        assertEquals("done\n", run.out());
        Path trace = folder.resolve("drive.out").resolve("trace.jsonl");
        assertTrue(Files.size(trace) <= 4096, Files.size(trace) + " bytes");
        List<String> lines = Files.readAllLines(trace);
        assertTrue(lines.get(lines.size() - 1).matches("\\{\"nanos\":\\d+,\"event\":\"trace-cut\",\"limit\":4096}"),
                lines.get(lines.size() - 1));
        assertTrue(run.err().contains("masl: the trace " + trace + " was cut at its limit of 4096 bytes (--trace-limit)\n"),
                "said as a plain run says it: " + run.err());
    }

    /** A world the simulator reads with a warning (it has no cone): said on standard error, positioned, and the run goes on. */
    @Test
    void theWarningsOfTheXodeFilesAreShownWithTheirPositions() throws IOException {
        Path scenario = scenario(DRIVE);
        Files.writeString(folder.resolve("floor.xode"), FLOOR.replace("</space>",
                "  <geom name=\"c\"><cone radius=\"1\" length=\"2\"/></geom>\n</space>"));

        Run run = Run.of("run", "--sim", scenario.toString(), "--quiet");

        assertEquals(0, run.status(), run.err());
        assertEquals("drove\n", run.out());
        List<String> lines = run.err().lines().toList();
        assertTrue(lines.get(0).matches(".*floor\\.xode:3:\\d+: warning: <cone>: ode4j has no cone: this geom is skipped"),
                run.err());
        assertTrue(lines.contains("1 warning"), run.err());
    }

    @Test
    void theJournalGoesToStandardOutputAndTheFilesNextToTheScenario() throws IOException {
        Run run = Run.of("run", "--sim", scenario(DRIVE).toString());
        assertEquals(0, run.status(), run.err());
        assertEquals("drove\n", run.out());
        Path out = folder.resolve("drive.out");
        assertTrue(run.err().contains("output in " + out), run.err());
        for (String file : new String[] {"trajectories.csv", "events.jsonl", "trace.jsonl", "journal.txt",
                "trajectories.png"}) {
            assertTrue(Files.isRegularFile(out.resolve(file)), file);
        }
        assertEquals("drove\n", Files.readString(out.resolve("journal.txt")));
    }

    @Test
    void outChoosesTheFolderAndTheSameSeedGivesTheSameTrajectories() throws IOException {
        Path scenario = scenario(DRIVE);
        Path first = folder.resolve("first");
        Path second = folder.resolve("second");
        assertEquals(0, Run.of("run", "--sim", scenario.toString(), "--out", first.toString(), "--seed", "9").status());
        assertEquals(0, Run.of("run", "--sim", scenario.toString(), "--out", second.toString(), "--seed", "9").status());
        assertEquals(Files.readString(first.resolve("trajectories.csv")),
                Files.readString(second.resolve("trajectories.csv")));
    }

    @Test
    void errorsInTheMissionArePositionedInItsFileWithStatusOne() throws IOException {
        Run run = Run.of("run", "--sim", scenario(DRIVE.replace(".stop()", ".fly()")).toString());
        assertEquals(1, run.status());
        assertEquals("", run.out());
        assertTrue(run.err().contains("drive.masl:6:4: error: cannot find primitive fly"), run.err());
    }

    @Test
    void anAgentTheMissionDoesNotDeclareIsAScenarioErrorWithStatusOne() throws IOException {
        Run run = Run.of("run", "--sim", scenario(DRIVE.replace("WheeledRobot k =", "WheeledRobot j =")).toString());
        assertEquals(1, run.status());
        assertTrue(run.err().contains("drive.scenario.xml:3:3: error: agent 'k' is not declared by the mission"),
                run.err());
    }

    @Test
    void anOutputFolderThatCannotBeWrittenIsReportedBeforeTheMissionRuns() throws IOException {
        Path scenario = scenario(DRIVE);
        Path file = Files.writeString(folder.resolve("taken"), "a file, not a folder");
        Path out = file.resolve("out");
        Run run = Run.of("run", "--sim", scenario.toString(), "--out", out.toString());
        assertEquals(new Run(2, "", "masl: cannot write the simulation's output to " + out + ": Not a directory ("
                + out + ")\n"), run);
        Run taken = Run.of("run", "--sim", scenario.toString(), "--out", file.toString());
        assertEquals(new Run(2, "", "masl: cannot write the simulation's output to " + file + ": " + file
                + " exists and is not a folder\n"), taken);
    }

    /** A physics step cannot be interrupted, so {@code --timeout} could not end a step of 2·10⁹ iterations. */
    @Test
    @Timeout(value = 120, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void scenarioNumbersThatWouldMakeAStepEndlessArePositionedErrors() throws IOException {
        Path scenario = scenario(DRIVE);
        Files.writeString(scenario, Files.readString(scenario).replace("<world", """
                <physics iterations="2000000000"/>
                  <world"""));
        Run run = Run.of("run", "--sim", scenario.toString(), "--timeout", "5");
        assertEquals(new Run(1, "", scenario + ":2:3: error: iterations: '2000000000' is not a whole number from 1"
                + " to 10000\n  <physics iterations=\"2000000000\"/>\n  ^\n1 error\n"), run);
    }

    @Test
    void aProgramOperandOrAMissingScenarioIsBadUsage() throws IOException {
        Path scenario = scenario(DRIVE);
        assertEquals(64, Run.of("run", "--sim", scenario.toString(), "drive.masl").status());
        assertEquals(64, Run.of("run", "--sim", folder.resolve("none.xml").toString()).status());
        assertEquals(64, Run.of("run", "--sim", scenario.toString(), "--threads").status());
    }

    @Test
    void optionsOfAJadePlatformOrOfAProgramsTraceAreBadUsageWithTheSimulatorNotIgnored() throws IOException {
        Path scenario = scenario(DRIVE);
        for (List<String> jade : List.of(List.of("--platform", "jade"), List.of("--deploy", "*=c2"),
                List.of("--place", "a=c2"), List.of("--main-host", "127.0.0.1", "--main-port", "1099"),
                List.of("--port", "1099"), List.of("--secret-file", "secret"))) {
            List<String> args = new ArrayList<>(List.of("run", "--sim", scenario.toString()));
            args.addAll(jade);
            Run run = Run.of(args.toArray(String[]::new));
            assertEquals(64, run.status(), String.join(" ", jade));
            assertTrue(run.err().contains("are for a JADE platform: --sim runs the mission and its simulated robots"
                    + " in this JVM"), run.err());
        }
        Run traced = Run.of("run", "--sim", scenario.toString(), "--trace", folder.resolve("t.jsonl").toString());
        assertEquals(64, traced.status());
        assertTrue(traced.err().contains("trace.jsonl in --out DIR"), traced.err());
        assertFalse(Files.exists(folder.resolve("t.jsonl")));
        assertFalse(Files.exists(folder.resolve("drive.out")), "nothing ran");
    }
}
