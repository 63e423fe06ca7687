package masl.testing;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

/**
 * An agent reaches an e-sequence (MASL §6.3) when it enters one of its blocks, or tests
 * and skips them all; failing the test of the first block only is not reaching it. Counting that
 * failure let the first block's free entry barrier open before the failing agents had tested the
 * second block, and some seeds then deadlocked.
 */
class ESequenceReachedTest {

    private static final int SEEDS = 300;

    private static String siblings(String first, String second) {
        return "import Default.xml;\nDefault a, b, c = newAgent(Default);\n" + """
                synchronous entry main (true) {
                  %s
                  %s
                  scalar entry end (true) { .logln(""); }
                }
                """.formatted(first, second);
    }

    private static final String LEFT = "synchronous entry left (.getProxyID() == 0) { .log(\"L\"); .log(\"L\"); }";
    private static final String RIGHT = "synchronous entry right (.getProxyID() != 0) { .log(\"R\"); .log(\"R\"); }";

    @Test
    void leftThenRightCompletesInLockStepUnderEverySeed() {
        assertLockStep(MaslMission.fromString("left-right.masl", siblings(LEFT, RIGHT)).explore(SEEDS));
    }

    @Test
    void rightThenLeftCompletesInLockStepUnderEverySeed() {
        assertLockStep(MaslMission.fromString("right-left.masl", siblings(RIGHT, LEFT)).explore(SEEDS));
    }

    /** Each agent logs one letter per step of its child, the steps of both children barrier-aligned. */
    private static void assertLockStep(Exploration exploration) {
        exploration.assertEveryRun(run -> {
            run.assertCompleted();
            String journal = run.journal();
            assertEquals(7, journal.length(), journal);
            assertEquals("LRR", sorted(journal.substring(0, 3)), journal);
            assertEquals("LRR", sorted(journal.substring(3, 6)), journal);
            assertEquals("\n", journal.substring(6), journal);
        });
    }

    private static String sorted(String text) {
        char[] characters = text.toCharArray();
        Arrays.sort(characters);
        return new String(characters);
    }
}
