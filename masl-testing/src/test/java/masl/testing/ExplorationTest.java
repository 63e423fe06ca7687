package masl.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/** Exploring seeded schedules finds the interleavings a mission's correctness depends on. */
@Tag("slow")
class ExplorationTest {

    /**
     * Three agents update a shared counter in an asynchronous child; the report comes after the
     * parent's barrier that ends the child (the {@code .nop()} keeps the two blocks from forming one
     * e-sequence, which would be one instruction, letting the report run before the others finish).
     */
    private static String counterMission(String increment) {
        return """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                synchronous entry main (true) {
                  shared int counter = 0;
                  asynchronous entry work (true) {
                    local int seen = 0;
                    %s
                  }
                  .nop();
                  scalar entry report (true) { .logln("counter=" + counter); }
                }
                """.formatted(increment);
    }

    @Test
    void readThenWriteThroughALocalLosesAnUpdateUnderSomeSeed() {
        MaslMission lostUpdate = MaslMission.fromString("lost-update.masl", counterMission("seen = counter;\n    counter = seen + 1;"));

        Exploration exploration = lostUpdate.explore(500);

        Optional<MissionRun> lost = exploration.findRun(run -> run.journal().equals("counter=2\n") || run.journal().equals("counter=1\n"));
        assertTrue(lost.isPresent(), exploration::report);
        assertTrue(exploration.distinctJournals().containsKey("counter=3\n"), exploration::report);
        AssertionError failure = assertThrows(AssertionError.class,
                () -> exploration.assertEveryRun(run -> run.assertJournal("counter=3\n")));
        assertTrue(failure.getMessage().contains("under seed "), failure.getMessage());
        assertTrue(failure.getMessage().contains("runs violate the property"), failure.getMessage());
    }

    @Test
    void anAtomicIncrementNeverLosesAnUpdate() {
        MaslMission atomic = MaslMission.fromString("atomic.masl", counterMission("counter++;"));

        Exploration exploration = atomic.explore(500);

        exploration.assertEveryRun(run -> run.assertJournal("counter=3\n"));
        assertEquals(1, exploration.distinctJournals().size());
    }
}
