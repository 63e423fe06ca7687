package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.List;
import masl.jade.platform.JadePlatform;
import masl.jade.platform.Readiness;
import masl.testing.jade.JadePlatformExtension;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The worked examples of examples.md (E1 to E8) run from their MASL sources inside
 * JADE, as a user runs them: {@code masl run FILE --platform jade}, joining a main container this
 * class starts once (JADE keeps a platform at least 3 s; and JADE's runtime, one per JVM, does not
 * shut a second main container down cleanly). The command's own platform, its default, is tested in
 * masl-cli ({@code JadeRunTest}). Each journal is the one examples.md states; standard error
 * stays empty.
 */
@Timeout(120)
@Tag("slow")
class JadeExamplesTest {

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void e1ScalarMainIsRunByOneAgent() {
        assertEquals("Hi team\n", maslJoined("e1_scalar_main.masl"));
    }

    @Test
    void e2SharedAndLocalVariablesInLockStep() {
        assertEquals("n=5\n" + "mine=1\n".repeat(5), maslJoined("e2_shared_and_local.masl"));
    }

    @Test
    void e3AsynchronousChildIsOneInstructionOfItsSynchronousParent() {
        assertEquals("xxxxxxyyyy\n", maslJoined("e3_asynchronous_child.masl"));
    }

    /** E4: four {@code heard now} (the first line), one line per worker after a {@code heard now}. */
    @Test
    void e4EventsAreReactedToInTheParentAndResume() {
        String journal = maslJoined("e4_events.masl");
        List<String> lines = journal.lines().toList();
        assertEquals(List.of("heard now", "heard now", "heard now", "heard now", "worker 1", "worker 2", "worker 3"),
                sorted(journal));
        assertEquals("heard now", lines.get(0));
    }

    @Test
    void e5DeniedInvocationBecomesTimeoutBeforeTheResultIsLogged() {
        assertEquals("timeout\nseen=0\n", maslJoined("e5_permeability.masl"));
    }

    @Test
    void e6LockedBlockAdmitsOneAgentPerWave() {
        assertEquals("in 1\n".repeat(3), maslJoined("e6_one_at_a_time.masl"));
    }

    @Test
    void e7ReelectThinsTheWaveOut() {
        assertEquals(List.of("0:1", "1:2", "2:3"), sorted(maslJoined("e7_reelect.masl")));
    }

    /** E8: two {@code in}, two {@code out}, no {@code never}; each agent's {@code in} precedes its {@code out}. */
    @Test
    void e8BreakLeavesTwoBlocks() {
        String journal = maslJoined("e8_break_out_of_two.masl");
        assertEquals(List.of("in", "in", "out", "out"), sorted(journal));
        int open = 0;
        for (String line : journal.split("\n")) {
            open += line.equals("in") ? 1 : -1;
            if (open < 0) {
                throw new AssertionError("an out before its agent's in:\n" + journal);
            }
        }
    }

    /** The journal of {@code masl run} on an example; fails unless the run succeeds, saying only that it is ready. */
    private static String maslJoined(String example) {
        JadePlatform platform = JADE.platform();
        MaslCommand run = MaslCommand.run("run", "src/test/resources/examples/" + example, "--platform", "jade",
                "--main-host", platform.host(), "--main-port", String.valueOf(platform.port()), "--timeout", "60");
        assertEquals(Readiness.platform(platform) + "\n", run.err());
        assertEquals(0, run.status());
        return run.out();
    }

    private static List<String> sorted(String journal) {
        return Arrays.stream(journal.split("\n")).sorted().toList();
    }
}
