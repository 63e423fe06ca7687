package masl.runtime.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.descriptor.AgentType;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.TestTypes;
import masl.runtime.trace.JsonLinesTrace;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** The worked examples of examples.md, hand-translated, give exactly the journals stated there. */
@Timeout(120)
class ExamplesTest {

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e1ScalarMainIsRunByOneAgent(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("Hi team\n", Missions.run(driver, E1ScalarMain.MAIN, 3, E1ScalarMain::new).journal());
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e2SharedAndLocalVariablesInLockStep(Driver driver) {
        String expected = "n=5\n" + "mine=1\n".repeat(5);
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals(expected, Missions.run(driver, E2SharedAndLocal.MAIN, 5, E2SharedAndLocal::new).journal());
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e3AsynchronousChildIsOneInstructionOfItsSynchronousParent(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("xxxxxxyyyy\n",
                    Missions.run(driver, E3AsynchronousChild.MAIN, 4, E3AsynchronousChild::new).journal());
        }
    }

    /** E4 runs 100 times in a row with each driver but the seeded one, which runs it with 20 seeds. */
    @ParameterizedTest
    @EnumSource(value = Driver.class, names = "SEEDED", mode = EnumSource.Mode.EXCLUDE)
    void e4EventsLookUpInTheParentAndResume(Driver driver) {
        for (int run = 0; run < 100; run++) {
            assertE4Journal(Missions.run(driver, E4Events.MAIN, 4, E4Events::new).journal());
        }
    }

    @Test
    void e4EventsWithTwentySeeds() {
        for (long seed = 1; seed <= 20; seed++) {
            assertE4Journal(Missions.run(new SeededScheduler(seed), E4Events.MAIN, 4, E4Events::new, Trace.NONE)
                    .journal());
        }
    }

    @Test
    void e4WithOneSeedGivesTheSameJournalAndTraceByteForByte() {
        for (long seed = 1; seed <= 5; seed++) {
            List<String> runs = new ArrayList<>();
            for (int run = 0; run < 2; run++) {
                StringWriter trace = new StringWriter();
                String journal = Missions.run(new SeededScheduler(seed), E4Events.MAIN, 4, E4Events::new,
                        new JsonLinesTrace(trace)).journal();
                runs.add(journal + trace);
            }
            assertTrue(runs.get(0).contains("\"event\":\"event-reacted\""), runs.get(0));
            assertEquals(runs.get(0), runs.get(1), "seed " + seed);
        }
    }

    /** examples.md: four "heard now", one line per worker, "heard now" first; the mission ended on its own. */
    private static void assertE4Journal(String journal) {
        assertEquals(List.of("heard now", "heard now", "heard now", "heard now", "worker 1", "worker 2", "worker 3"),
                sortedLines(journal), journal);
        assertTrue(journal.startsWith("heard now\n"), journal);
    }

    /** E5 runs 100 times in a row with each driver; the trace shows the denial by b's state. */
    @ParameterizedTest
    @EnumSource(Driver.class)
    void e5DeniedInvocationBecomesTimeout(Driver driver) {
        AgentType type = TestTypes.testAgent();
        for (int run = 0; run < 100; run++) {
            AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(2);
            StringWriter trace = new StringWriter();
            String journal = Missions.run(driver.newScheduler(), E5Permeability.MAIN, 2, type,
                    self -> new E5Permeability(self, population), new JsonLinesTrace(trace)).journal();
            assertEquals("timeout\nseen=0\n", journal);
            assertTrue(trace.toString().contains("\"event\":\"invocation-denied\",\"requester\":0,\"callee\":1,"
                    + "\"member\":\"getProxyID\",\"state\":\"nothing\""), trace.toString());
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e6LockedBlockAdmitsOneAgentPerWave(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("in 1\nin 1\nin 1\n", Missions.run(driver, E6OneAtATime.MAIN, 4, E6OneAtATime::new).journal());
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e7ReelectThinsTheWaveOut(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            String journal = Missions.run(driver, E7Reelect.MAIN, 3, E7Reelect::new).journal();
            assertEquals(List.of("0:1", "1:2", "2:3"), sortedLines(journal));
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e8BreakLeavesTwoBlocks(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            String journal = Missions.run(driver, E8BreakOutOfTwo.MAIN, 2, E8BreakOutOfTwo::new).journal();
            assertEquals(List.of("in", "in", "out", "out"), sortedLines(journal));
            // Each agent's "in" precedes its "out": so the journal cannot start with "out".
            assertTrue(journal.startsWith("in\n"), journal);
            assertEquals(2, journal.indexOf("out") > journal.indexOf("in") ? 2 : 0, journal);
        }
    }

    private static List<String> sortedLines(String journal) {
        List<String> lines = new ArrayList<>(Arrays.asList(journal.split("\n")));
        Collections.sort(lines);
        return lines;
    }
}
