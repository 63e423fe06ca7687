package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.function.Consumer;
import masl.e2e.Missions.Driver;
import masl.translator.MissionLoader;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The worked examples of examples.md, translated from their MASL source: each run many times with
 * the pool scheduler and with a thread per agent, and over seeds of the deterministic scheduler,
 * gives the journal (or satisfies the journal constraints) examples.md states.
 */
@Timeout(300)
class ExamplesTest {

    private static final int RUNS = 50;
    private static final int SEEDS = 10;

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e1ScalarMainIsRunByOneAgent(Driver driver) {
        repeat("e1_scalar_main.masl", driver, journal -> assertEquals("Hi team\n", journal));
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e2SharedAndLocalVariablesInLockStep(Driver driver) {
        repeat("e2_shared_and_local.masl", driver, journal -> assertEquals("n=5\n" + "mine=1\n".repeat(5), journal));
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e3AsynchronousChildIsOneInstructionOfItsSynchronousParent(Driver driver) {
        repeat("e3_asynchronous_child.masl", driver, journal -> assertEquals("xxxxxxyyyy\n", journal));
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e6LockedBlockAdmitsOneAgentPerWave(Driver driver) {
        repeat("e6_one_at_a_time.masl", driver, journal -> assertEquals("in 1\n".repeat(3), journal));
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e7ReelectThinsTheWaveOut(Driver driver) {
        repeat("e7_reelect.masl", driver, ExamplesTest::assertE7);
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void e8BreakLeavesTwoBlocks(Driver driver) {
        repeat("e8_break_out_of_two.masl", driver, ExamplesTest::assertE8);
    }

    @Test
    void examplesHoldOverSeeds() {
        for (long seed = 1; seed <= SEEDS; seed++) {
            long s = seed;
            assertEquals("Hi team\n", seeded("e1_scalar_main.masl", s));
            assertEquals("n=5\n" + "mine=1\n".repeat(5), seeded("e2_shared_and_local.masl", s));
            assertEquals("xxxxxxyyyy\n", seeded("e3_asynchronous_child.masl", s));
            assertEquals("in 1\n".repeat(3), seeded("e6_one_at_a_time.masl", s));
            assertE7(seeded("e7_reelect.masl", s));
            assertE8(seeded("e8_break_out_of_two.masl", s));
        }
    }

    @Test
    void aSeedReplaysItsJournal() {
        MissionLoader e8 = Missions.example("e8_break_out_of_two.masl");
        for (long seed = 1; seed <= SEEDS; seed++) {
            assertEquals(Missions.journalWithSeed(e8, seed), Missions.journalWithSeed(e8, seed), "seed " + seed);
        }
    }

    private static String seeded(String example, long seed) {
        return Missions.journalWithSeed(Missions.example(example), seed);
    }

    private static void repeat(String example, Driver driver, Consumer<String> assertion) {
        MissionLoader loaded = Missions.example(example);
        for (int run = 0; run < RUNS; run++) {
            assertion.accept(Missions.journal(loaded, driver));
        }
    }

    /** E7: {@code 0:1}, {@code 1:2}, {@code 2:3} in some order. */
    private static void assertE7(String journal) {
        assertEquals(List.of("0:1", "1:2", "2:3"), sortedLines(journal), journal);
    }

    /** E8: two {@code in}, two {@code out}, no {@code never}; each agent's {@code in} precedes its {@code out}. */
    private static void assertE8(String journal) {
        assertEquals(List.of("in", "in", "out", "out"), sortedLines(journal), journal);
        int ins = 0;
        int outs = 0;
        for (String line : journal.split("\n")) {
            if (line.equals("in")) {
                ins++;
            } else {
                outs++;
            }
            assertTrue(outs <= ins, "an out before its agent's in: " + journal);
        }
    }

    private static List<String> sortedLines(String journal) {
        List<String> lines = new ArrayList<>(Arrays.asList(journal.split("\n")));
        Collections.sort(lines);
        return lines;
    }
}
