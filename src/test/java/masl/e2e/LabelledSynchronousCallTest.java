package masl.e2e;

import java.util.stream.LongStream;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.Schedule;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A labelled call of a synchronous primitive completes before the instruction ends (MASL §10):
 * right after {@code l.got = b.twice(i);} the label has nothing pending and
 * {@code got} holds the result. The two Workers call each other, so every call is external and
 * is served on the callee's thread while the caller waits: the case where the caller used to wake
 * before the label had counted the call.
 */
@Timeout(60)
class LabelledSynchronousCallTest {

    private static final int SEEDS = 400;
    private static final int POOL_RUNS = 300;
    private static final int THREAD_RUNS = 300;
    private static final int DEPLOYED_RUNS = 5;

    /** Each agent makes ten labelled calls and checks the label and the stored result right after each. */
    private static final MaslMission MISSION = MaslMission.fromString("labelled-synchronous.masl", """
            import workers/Worker.xml;
            Worker a, b = newAgent(Worker);
            synchronous entry main (true) {
              LLabel l;
              local int got = 0;
              local int i = 0;
              local int remaining = 0;
              local int seen = 0;
              local int late = 0;
              for (i = 1; i <= 10; i++) {
                if (.getProxyID() == 0) l.got = b.twice(i); else l.got = a.twice(i);
                remaining = l.getRemainingInvocations();
                seen = got;
                if (remaining != 0 || seen != 2 * i) {
                  late++;
                  .logln(.getProxyID() + " call " + i + ": remaining " + remaining + ", got " + seen);
                }
              }
              if (.getProxyID() == 0) l.b.drain(1); else l.a.drain(2);
              .logln(.getProxyID() + ": " + late + " late, then remaining " + l.getRemainingInvocations()
                  + ", finished " + l.isFinished());
            }
            """);

    /**
     * A boss collects two asynchronous calls of {@code a} with a label, one stored into {@code b}'s
     * attribute, and opens {@code a}'s gate once it has launched both.
     */
    private static final MaslMission ASYNCHRONOUS = MaslMission.fromString("labelled-asynchronous.masl", """
            import workers/Worker.xml;
            Worker a, b, boss = newAgent(Worker);
            asynchronous entry main (true) {
              scalar entry collect (.getProxyID() == 2) {
                LLabel l;
                local int ra = 0;
                l.ra = a.slow(1);
                l.b.battery = a.slow(2);
                .logln("launched: remaining " + l.getRemainingInvocations() + ", ra " + ra);
                .open(a);
                while (l.getRemainingInvocations() > 0) {}
                .logln("came: ra " + ra + ", battery " + b.battery);
              }
            }
            """);

    @Test
    void rightAfterALabelledSynchronousCallNothingIsPendingAndTheResultIsStored() {
        MISSION.explore(LongStream.range(0, SEEDS), POOL_RUNS).assertEveryRun(LabelledSynchronousCallTest::counted);
        for (int run = 0; run < THREAD_RUNS; run++) {
            counted(MISSION.runWith(Schedule.threads()));
        }
    }

    /** Asynchronous calls keep their futures: counted until they come; a busy-wait on the count parks until then. */
    @Test
    void labelledAsynchronousCallsStayRemainingUntilTheyCome() {
        ASYNCHRONOUS.explore(LongStream.range(0, 50), 20).assertEveryRun(LabelledSynchronousCallTest::cameLate);
    }

    /**
     * The same with the programs deployed, whose labels are views of the mission's: every agent's in one
     * container, then the two callers' in two (each call crossing to the other), then one caller's alone
     * (its callee's program in the mission's JVM). The boss opens its callee's gate on its object, so the
     * two share a container; spread over two, {@code b}, whose attribute the label stores into, is in the other.
     */
    @Test
    void deployedProgramsSeeTheirLabelsAsInProcess() {
        for (int run = 0; run < DEPLOYED_RUNS; run++) {
            counted(MISSION.runOn(DeployedInMemory.everyAgent()));
            counted(MISSION.runOn(DeployedInMemory.spread()));
            counted(MISSION.runOn(DeployedInMemory.agents("a")));
            cameLate(ASYNCHRONOUS.runOn(DeployedInMemory.spread()));
        }
    }

    private static void cameLate(MissionRun run) {
        run.assertJournal("launched: remaining 2, ra 0\ncame: ra 10, battery 20\n");
    }

    private static void counted(MissionRun run) {
        run.assertLinesInAnyOrder("0: 0 late, then remaining 0, finished true",
                "1: 0 late, then remaining 0, finished true");
    }
}
