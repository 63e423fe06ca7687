package masl.testing;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;

/** The assertions a user's test makes on one run, and what their failures say. */
class MissionRunTest {

    private static final MaslMission E2 = MaslMission.fromString("e2.masl", """
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
            """);

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
    void aFailedAssertionNamesTheMissionAndTheSeedToReplay() {
        MissionRun run = E2.runWith(Schedule.seed(42));

        AssertionError failure = assertThrows(AssertionError.class, () -> run.assertJournal("n=4\n"));

        assertTrue(failure.getMessage().startsWith("e2.masl under seed 42 (replay: "), failure.getMessage());
        assertTrue(failure.getMessage().contains("masl run --seed 42"), failure.getMessage());
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
