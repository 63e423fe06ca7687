package masl.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** A seed reproduces a run, journal and trace alike. */
class ReplayTest {

    /** Asynchronous interleavings, a scalar block run by whichever agent comes first, a sleep. */
    private static final MaslMission MIXED = MaslMission.fromString("mixed.masl", """
            import Default.xml as Default;
            Default a0, a1, a2, a3 = newAgent(Default);
            synchronous entry main (true) {
              asynchronous entry evens (.getProxyID() % 2 == 0) {
                .log("x" + .getProxyID()); .sleep(5); .log("x" + .getProxyID());
              }
              .log("y" + .getProxyID());
              scalar entry end (true) { .logln(" by " + .getProxyID()); }
            }
            """);

    @Test
    void everySeedReplaysItsJournalAndTraceExactly() {
        Set<String> journals = new HashSet<>();
        for (long seed = 0; seed < 100; seed++) {
            MissionRun first = MIXED.runWith(Schedule.seed(seed)).assertCompleted();
            MissionRun replay = MIXED.runWith(Schedule.seed(seed)).assertCompleted();

            assertEquals(first.journal(), replay.journal(), "seed " + seed);
            assertEquals(first.trace(), replay.trace(), "seed " + seed);
            journals.add(first.journal());
        }
        assertTrue(journals.size() > 1, "100 seeds explored a single interleaving: " + journals);
    }
}
