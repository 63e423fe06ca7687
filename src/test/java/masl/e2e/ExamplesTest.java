package masl.e2e;

import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import java.util.stream.LongStream;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.Schedule;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The worked examples of examples.md, translated from their MASL source (with masl-testing, as a
 * user would test a mission): each run 50 times on the pool and 50 times with a thread per agent,
 * and explored over 500 seeds of the deterministic scheduler, gives the journal (or satisfies the
 * journal constraints) examples.md states. Exploration catches a property that holds by luck.
 */
@Timeout(60)
class ExamplesTest {

    private static final int RUNS = 50;
    /** E4 passes 100 times in a row, on each scheduler. */
    private static final int E4_RUNS_IN_A_ROW = 100;
    /** E5 gives exactly its journal 100 times in a row, on each scheduler. */
    private static final int E5_RUNS_IN_A_ROW = 100;
    private static final int SEEDS = 500;

    static List<Schedule> realSchedulers() {
        return List.of(Schedule.pool(), Schedule.threads());
    }

    @ParameterizedTest
    @MethodSource("realSchedulers")
    void e1ScalarMainIsRunByOneAgent(Schedule schedule) {
        repeat("e1_scalar_main.masl", schedule, run -> run.assertJournal("Hi team\n"));
    }

    @ParameterizedTest
    @MethodSource("realSchedulers")
    void e2SharedAndLocalVariablesInLockStep(Schedule schedule) {
        repeat("e2_shared_and_local.masl", schedule, ExamplesTest::assertE2);
    }

    @ParameterizedTest
    @MethodSource("realSchedulers")
    void e3AsynchronousChildIsOneInstructionOfItsSynchronousParent(Schedule schedule) {
        repeat("e3_asynchronous_child.masl", schedule, run -> run.assertJournal("xxxxxxyyyy\n"));
    }

    @ParameterizedTest
    @MethodSource("realSchedulers")
    void e4EventsAreReactedToInTheParentAndResume(Schedule schedule) {
        MaslMission e4 = example("e4_events.masl");
        for (int run = 0; run < E4_RUNS_IN_A_ROW; run++) {
            assertE4(e4.runWith(schedule));
        }
    }

    @ParameterizedTest
    @MethodSource("realSchedulers")
    void e5DeniedInvocationBecomesTimeoutBeforeTheResultIsLogged(Schedule schedule) {
        MaslMission e5 = example("e5_permeability.masl");
        for (int run = 0; run < E5_RUNS_IN_A_ROW; run++) {
            e5.runWith(schedule).assertJournal("timeout\nseen=0\n");
        }
    }

    @ParameterizedTest
    @MethodSource("realSchedulers")
    void e6LockedBlockAdmitsOneAgentPerWave(Schedule schedule) {
        repeat("e6_one_at_a_time.masl", schedule, run -> run.assertJournal("in 1\n".repeat(3)));
    }

    @ParameterizedTest
    @MethodSource("realSchedulers")
    void e7ReelectThinsTheWaveOut(Schedule schedule) {
        repeat("e7_reelect.masl", schedule, ExamplesTest::assertE7);
    }

    @ParameterizedTest
    @MethodSource("realSchedulers")
    void e8BreakLeavesTwoBlocks(Schedule schedule) {
        repeat("e8_break_out_of_two.masl", schedule, ExamplesTest::assertE8);
    }

    @Test
    void examplesHoldOverFiveHundredSeeds() {
        explore("e1_scalar_main.masl", run -> run.assertJournal("Hi team\n"));
        explore("e2_shared_and_local.masl", ExamplesTest::assertE2);
        explore("e3_asynchronous_child.masl", run -> run.assertJournal("xxxxxxyyyy\n"));
        explore("e4_events.masl", ExamplesTest::assertE4);
        explore("e5_permeability.masl", run -> run.assertJournal("timeout\nseen=0\n"));
        explore("e6_one_at_a_time.masl", run -> run.assertJournal("in 1\n".repeat(3)));
        explore("e7_reelect.masl", ExamplesTest::assertE7);
        explore("e8_break_out_of_two.masl", ExamplesTest::assertE8);
    }

    private static MaslMission example(String name) {
        return MaslMission.fromFile(Path.of("src/test/resources/examples", name));
    }

    private static void repeat(String name, Schedule schedule, Consumer<MissionRun> property) {
        MaslMission mission = example(name);
        for (int run = 0; run < RUNS; run++) {
            property.accept(mission.runWith(schedule));
        }
    }

    private static void explore(String name, Consumer<MissionRun> property) {
        example(name).explore(LongStream.range(0, SEEDS), 0).assertEveryRun(property);
    }

    /** E2: {@code n=5} then five lines {@code mine=1}. */
    private static void assertE2(MissionRun run) {
        run.assertJournal("n=5\n" + "mine=1\n".repeat(5));
    }

    /** E4: four {@code heard now}, one line per worker, in some order; the first line is {@code heard now}. */
    private static void assertE4(MissionRun run) {
        run.assertLinesInAnyOrder("heard now", "heard now", "heard now", "heard now", "worker 1", "worker 2",
                "worker 3");
        if (!run.journal().startsWith("heard now\n")) {
            throw new AssertionError(run + ": the first line is not heard now:\n" + run.journal());
        }
    }

    /** E7: {@code 0:1}, {@code 1:2}, {@code 2:3} in some order. */
    private static void assertE7(MissionRun run) {
        run.assertLinesInAnyOrder("0:1", "1:2", "2:3");
    }

    /** E8: two {@code in}, two {@code out}, no {@code never}; each agent's {@code in} precedes its {@code out}. */
    private static void assertE8(MissionRun run) {
        run.assertLinesInAnyOrder("in", "in", "out", "out");
        int ins = 0;
        int outs = 0;
        for (String line : run.journalLines()) {
            if (line.equals("in")) {
                ins++;
            } else {
                outs++;
            }
            if (outs > ins) {
                throw new AssertionError(run + ": an out before its agent's in:\n" + run.journal());
            }
        }
    }
}
