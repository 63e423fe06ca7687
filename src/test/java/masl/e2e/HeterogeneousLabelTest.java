package masl.e2e;

import java.util.List;
import java.util.function.Consumer;
import java.util.stream.LongStream;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.Schedule;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Labels over members only some types have (MASL §4, §10): for an addressee whose
 * type lacks the primitive, the label's invocation is a {@code nop()} that counts as done at once and
 * stores nothing. A team of a Worker and a Scout ({@code src/test/resources/workers}): only the Scout
 * has {@code sweep} (asynchronous), {@code scan} (synchronous) and {@code range}. The same
 * journals with the agents' programs deployed to containers, the mission holding the labels.
 */
@Timeout(60)
class HeterogeneousLabelTest {

    private static final int RUNS = 20;
    private static final int SEEDS = 200;
    /**
     * Runs with the agents' programs deployed over two containers, then the scout's alone, then the
     * worker's alone (the other's in the mission's JVM): a label's store into the other agent's attribute
     * crosses to where it runs, in each direction.
     */
    private static final int DEPLOYED_RUNS = 5;

    static List<Schedule> schedules() {
        return List.of(Schedule.pool(), Schedule.threads());
    }

    /**
     * Each agent addresses the other: the worker's label invocations reach the scout, the scout's
     * reach the worker, which lacks them. Only the scout sweeps, each sweep once; the scout's
     * variables keep their values; both labels finish.
     */
    @ParameterizedTest
    @MethodSource("schedules")
    void onlyTheAgentsWithThePrimitiveRunItAndTheLabelFinishes(Schedule schedule) {
        everyRun(schedule, "others", """
                Worker w = newAgent(Worker);
                Worker s = newAgent(Scout);
                asynchronous entry main (true) {
                    LLabel l;
                    local int swept = -1;
                    local int scanned = -1;
                    local Worker other = w;
                    if (.getProxyID() == 0) other = s;
                    l.other.sweep(2);
                    l.swept = other.sweep(3);
                    l.scanned = other.scan();
                    l.other.range = other.scan();
                    while (!l.isFinished()) {}
                    .logln(.getProxyID() + ": swept " + swept + ", scanned " + scanned + ", range " + other.range);
                }
                """, run -> run.assertLinesInAnyOrder("1 sweeps 2", "1 sweeps 3", "0: swept 30, scanned 7, range 7",
                        "1: swept -1, scanned -1, range 0"));
    }

    /** {@code l.m()} and {@code l.this.m()} of a primitive the agent's own type lacks: a nop() for that agent. */
    @ParameterizedTest
    @MethodSource("schedules")
    void anAgentWhoseTypeLacksThePrimitiveSkipsItsOwnLabelInvocation(Schedule schedule) {
        everyRun(schedule, "self", """
                Worker w = newAgent(Worker);
                Worker s = newAgent(Scout);
                synchronous entry main (true) {
                    SLabel l;
                    local int scanned = -1;
                    l.sweep(.getProxyID() + 4);
                    l.this.sweep(6);
                    l.this.scan();
                    l.scanned = .scan();
                    l.this.range = .scan();
                    while (!l.isFinished()) {}
                    .logln(.getProxyID() + ": scanned " + scanned + ", finished " + l.isFinished());
                }
                """, run -> run.assertLinesInAnyOrder("1 sweeps 5", "1 sweeps 6", "0: scanned -1, finished true",
                        "1: scanned 7, finished true"));
    }

    /**
     * A named agent is addressed as the type it was created with: a Worker may be a Scout, a soft
     * robot never is (no subtype of it has sweep), so {@code l.r.sweep()} is a nop for every caller.
     */
    @Test
    void aNamedAgentCreatedWithATypeWithoutThePrimitiveIsANopForEveryCaller() {
        MaslMission mission = MaslMission.fromString("named.masl", """
                import workers/Worker.xml;
                import workers/Scout.xml;
                import SoftWheeledRobot.xml as Soft;
                Worker w = newAgent(Worker);
                Soft r = newAgent(Soft);
                Scout s = newAgent(Scout);
                asynchronous entry main (true) {
                    LLabel l;
                    local int swept = -1;
                    l.w.sweep(1);
                    l.r.sweep(2);
                    l.swept = r.sweep(3);
                    l.s.sweep(.getProxyID() + 10);
                    while (!l.isFinished()) {}
                    .logln(.getProxyID() + " swept " + swept);
                }
                """);
        mission.run().assertLinesInAnyOrder("2 sweeps 10", "2 sweeps 11", "2 sweeps 12", "0 swept -1", "1 swept -1",
                "2 swept -1");
    }

    private static void everyRun(Schedule schedule, String name, String program, Consumer<MissionRun> property) {
        MaslMission mission = MaslMission.fromString(name + ".masl", "import workers/Worker.xml;\nimport workers/Scout.xml;\n" + program);
        for (int run = 0; run < RUNS; run++) {
            property.accept(mission.runWith(schedule));
        }
        if (schedule.equals(Schedule.threads())) {
            mission.explore(LongStream.range(0, SEEDS), 0).assertEveryRun(property);
            for (int run = 0; run < DEPLOYED_RUNS; run++) {
                property.accept(mission.runOn(DeployedInMemory.spread()));
                property.accept(mission.runOn(DeployedInMemory.agents("s")));
                property.accept(mission.runOn(DeployedInMemory.agents("w")));
            }
        }
    }
}
