package masl.runtime.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.function.Function;
import masl.jade.JadeLauncher;
import masl.jade.TestPrograms;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.MissionOutcome;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.testing.jade.JadePlatformExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The hand-translated examples of examples.md (masl-runtime's test sources; this class shares their
 * package to reach them) run inside JADE, in one container, give the journals they give in-process:
 * identical where examples.md fixes the journal, the same lines under the same constraints where it
 * allows several orders. Each mission is repeated {@value #REPETITIONS} times on one platform.
 */
@Timeout(60)
class JadeExamplesTest {

    private static final int REPETITIONS = 20;
    private static final Duration TIMEOUT = Duration.ofSeconds(30);

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void e1ScalarMain() throws Exception {
        assertSameJournalEveryTime(E1ScalarMain.MAIN, 3, E1ScalarMain::new, Order.FIXED);
    }

    @Test
    void e2SharedAndLocalVariablesInLockStep() throws Exception {
        assertSameJournalEveryTime(E2SharedAndLocal.MAIN, 5, E2SharedAndLocal::new, Order.FIXED);
    }

    @Test
    void e3AsynchronousChildInsideASynchronousParent() throws Exception {
        assertSameJournalEveryTime(E3AsynchronousChild.MAIN, 4, E3AsynchronousChild::new, Order.FIXED);
    }

    @Test
    void e4EventsLookUpInTheParentAndResume() throws Exception {
        List<String> journals = assertSameJournalEveryTime(E4Events.MAIN, 4, E4Events::new, Order.ANY);
        journals.forEach(journal -> assertTrue(journal.startsWith("heard now\n"), journal));
    }

    @Test
    void e6OneAtATimeThroughALockedBlock() throws Exception {
        assertSameJournalEveryTime(E6OneAtATime.MAIN, 4, E6OneAtATime::new, Order.FIXED);
    }

    @Test
    void e7ReelectThinsTheWaveOut() throws Exception {
        assertSameJournalEveryTime(E7Reelect.MAIN, 3, E7Reelect::new, Order.ANY);
    }

    @Test
    void e8BreakOutOfTwoBlocks() throws Exception {
        List<String> journals = assertSameJournalEveryTime(E8BreakOutOfTwo.MAIN, 2, E8BreakOutOfTwo::new, Order.ANY);
        // Each agent's "in" precedes its "out", so a journal starts with "in" and ends with "out".
        journals.forEach(journal -> assertTrue(journal.startsWith("in\n") && journal.endsWith("out\n"), journal));
    }

    /** Whether examples.md fixes the order of the journal's lines. */
    private enum Order { FIXED, ANY }

    /** Runs the example in-process once and in JADE {@link #REPETITIONS} times; returns the JADE journals. */
    private static List<String> assertSameJournalEveryTime(EntryDefinition main, int agents,
            Function<TestAgent, AgentProgram> program, Order order) throws Exception {
        String inProcess = Missions.run(Driver.THREADS, main, agents, program).journal();
        JadeLauncher launcher = JadeLauncher.of(TestPrograms.of(main, agents, program)).types(TestPrograms::type);
        String[] journals = new String[REPETITIONS];
        for (int run = 0; run < REPETITIONS; run++) {
            MissionOutcome outcome = launcher.run(JADE.platform(), TIMEOUT).requireCompleted();
            journals[run] = outcome.journal();
            assertEquals(order == Order.FIXED ? inProcess : sortedLines(inProcess),
                    order == Order.FIXED ? outcome.journal() : sortedLines(outcome.journal()), "run " + run);
        }
        return List.of(journals);
    }

    private static String sortedLines(String journal) {
        String[] lines = journal.split("\n", -1);
        Arrays.sort(lines);
        return String.join("\n", lines);
    }
}
