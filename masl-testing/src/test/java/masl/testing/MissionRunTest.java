package masl.testing;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The assertions a user's test makes on one run, and what their failures say. */
class MissionRunTest {

    private static final String E2_TEXT = """
            import Default.xml as Default;
            Default a, b, c, d, e = newAgent(Default);
            synchronous entry main (true) {
              shared int n = 0;
              local int mine = 0;
              n++;
              mine++;
              scalar entry report (true) { .logln("n=" + n); }
              .logln("mine=" + mine);
            }
            """;
    private static final MaslMission E2 = MaslMission.fromString("e2.masl", E2_TEXT);

    @Test
    void journalAssertionsHoldOnExampleE2() {
        E2.runWith(Schedule.seed(7))
                .assertJournal("n=5\nmine=1\nmine=1\nmine=1\nmine=1\nmine=1\n")
                .assertLinesInAnyOrder("mine=1", "mine=1", "n=5", "mine=1", "mine=1", "mine=1")
                .assertEveryBefore("n=.*", "mine=.*")
                .assertTraceHas(TraceEvent.Entered.class, entered -> entered.block().equals("report"), "entering report")
                .assertTraceHasNo(TraceEvent.Entered.class, entered -> entered.block().equals("nowhere"), "no block nowhere");
    }

    @Test
    void aFailedAssertionNamesTheMissionAndTheSeedToReplayInTheTest() {
        MissionRun run = E2.runWith(Schedule.seed(42));

        AssertionError failure = assertThrows(AssertionError.class, () -> run.assertJournal("n=4\n"));

        assertTrue(failure.getMessage().startsWith("e2.masl under seed 42: journal differs"), failure.getMessage());
        assertTrue(failure.getMessage().endsWith("\nreplay: runWith(Schedule.seed(42L))"), failure.getMessage());
        assertFalse(failure.getMessage().contains("masl run"), "a program given as text is no file masl can run: "
                + failure.getMessage());
    }

    @Test
    void aProgramFromAFileIsReplayedWithMaslRunItsAgentPathAndCallTimeout(@TempDir Path folder) throws IOException {
        Path program = Files.writeString(folder.resolve("e2.masl"), E2_TEXT);
        MissionRun run = MaslMission.fromFile(program).agentPath("robots:lib/arm.jar").callTimeout(Duration.ofMillis(500))
                .runWith(Schedule.seed(42));

        AssertionError failure = assertThrows(AssertionError.class, () -> run.assertJournal("n=4\n"));

        assertTrue(failure.getMessage().endsWith("\nreplay: runWith(Schedule.seed(42L)), or masl run " + program
                + " --agent-path robots:lib/arm.jar --call-timeout 500 --seed 42"), failure.getMessage());
    }

    @Test
    void aRunOffTheSeedHasNoReplayHint() {
        MissionRun run = E2.runWith(Schedule.threads());

        AssertionError failure = assertThrows(AssertionError.class, () -> run.assertJournal("n=4\n"));

        assertTrue(failure.getMessage().startsWith("e2.masl under one thread per agent: journal differs"), failure.getMessage());
        assertFalse(failure.getMessage().contains("replay"), failure.getMessage());
    }

    @Test
    void anOrderingConstraintFailsWhenALaterLineComesFirst() {
        MissionRun run = E2.run();

        assertThrows(AssertionError.class, () -> run.assertEveryBefore("mine=.*", "n=.*"));
        assertThrows(AssertionError.class, () -> run.assertEveryBefore("n=.*", "absent"));
    }

    @Test
    void aProgramWithErrorsFailsWithItsDiagnostics() {
        MaslMission broken = MaslMission.fromString("broken.masl", "import Default.xml as Default;\nDefault a = newAgent(Default);\nscalar entry main (true) { .logln(\"x\"; }\n");

        AssertionError failure = assertThrows(AssertionError.class, broken::run);

        assertTrue(failure.getMessage().contains("broken.masl:3:"), failure.getMessage());
    }
}
