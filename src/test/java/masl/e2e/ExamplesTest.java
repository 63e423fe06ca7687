package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import java.util.stream.Stream;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.Schedule;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The worked examples of examples.md, translated from their MASL source in
 * {@code src/test/resources/examples}: each run 50 times with the pool scheduler and 50 times with a
 * thread per agent, and under 10 seeds of the deterministic scheduler, gives the journal (or satisfies
 * the journal constraints) examples.md states.
 */
@Timeout(300)
class ExamplesTest {

    private static final int RUNS = 50;
    private static final int SEEDS = 10;
    private static final Path EXAMPLES = Path.of("src", "test", "resources", "examples");
    private static final Map<String, MaslMission> MISSIONS = new ConcurrentHashMap<>();

    private static final Consumer<MissionRun> E1 = run -> run.assertJournal("Hi team\n");
    private static final Consumer<MissionRun> E2 = run -> run.assertJournal("n=5\n" + "mine=1\n".repeat(5));
    private static final Consumer<MissionRun> E3 = run -> run.assertJournal("xxxxxxyyyy\n");
    private static final Consumer<MissionRun> E6 = run -> run.assertJournal("in 1\n".repeat(3));
    private static final Consumer<MissionRun> E7 = run -> run.assertLinesInAnyOrder("0:1", "1:2", "2:3");
    /** Two {@code in}, two {@code out}, no {@code never}; each agent's {@code in} precedes its {@code out}. */
    private static final Consumer<MissionRun> E8 = run -> {
        run.assertLinesInAnyOrder("in", "in", "out", "out");
        int ins = 0;
        int outs = 0;
        for (String line : run.journalLines()) {
            ins += line.equals("in") ? 1 : 0;
            outs += line.equals("out") ? 1 : 0;
            assertTrue(outs <= ins, "an out before its agent's in under " + run.schedule() + ":\n" + run.journal());
        }
    };

    static Stream<Schedule> schedulers() {
        return Stream.of(Schedule.pool(), Schedule.threads());
    }

    @ParameterizedTest
    @MethodSource("schedulers")
    void e1ScalarMainIsRunByOneAgent(Schedule schedule) {
        repeat("e1_scalar_main.masl", schedule, E1);
    }

    @ParameterizedTest
    @MethodSource("schedulers")
    void e2SharedAndLocalVariablesInLockStep(Schedule schedule) {
        repeat("e2_shared_and_local.masl", schedule, E2);
    }

    @ParameterizedTest
    @MethodSource("schedulers")
    void e3AsynchronousChildIsOneInstructionOfItsSynchronousParent(Schedule schedule) {
        repeat("e3_asynchronous_child.masl", schedule, E3);
    }

    @ParameterizedTest
    @MethodSource("schedulers")
    void e6LockedBlockAdmitsOneAgentPerWave(Schedule schedule) {
        repeat("e6_one_at_a_time.masl", schedule, E6);
    }

    @ParameterizedTest
    @MethodSource("schedulers")
    void e7ReelectThinsTheWaveOut(Schedule schedule) {
        repeat("e7_reelect.masl", schedule, E7);
    }

    @ParameterizedTest
    @MethodSource("schedulers")
    void e8BreakLeavesTwoBlocks(Schedule schedule) {
        repeat("e8_break_out_of_two.masl", schedule, E8);
    }

    @Test
    void everyExampleHoldsUnderSeeds() {
        example("e1_scalar_main.masl").explore(SEEDS).assertEveryRun(E1);
        example("e2_shared_and_local.masl").explore(SEEDS).assertEveryRun(E2);
        example("e3_asynchronous_child.masl").explore(SEEDS).assertEveryRun(E3);
        example("e6_one_at_a_time.masl").explore(SEEDS).assertEveryRun(E6);
        example("e7_reelect.masl").explore(SEEDS).assertEveryRun(E7);
        example("e8_break_out_of_two.masl").explore(SEEDS).assertEveryRun(E8);
    }

    private static MaslMission example(String file) {
        return MISSIONS.computeIfAbsent(file, name -> MaslMission.fromFile(EXAMPLES.resolve(name)));
    }

    private static void repeat(String file, Schedule schedule, Consumer<MissionRun> property) {
        MaslMission mission = example(file);
        for (int run = 0; run < RUNS; run++) {
            property.accept(mission.runWith(schedule).assertCompleted());
        }
    }
}
