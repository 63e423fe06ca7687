package masl.e2e;

import java.util.List;
import java.util.function.Consumer;
import masl.testing.MaslMission;
import masl.testing.MissionPlatform;
import masl.testing.MissionRun;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The manual's labels (§10) with the agents' programs deployed: the mission holds the labels, the
 * programs' views ask it; the journals are those in-process gives. Every agent's program in one
 * container, then over two, then one agent's alone, so that a label travels between containers and
 * between a container and the mission's JVM (an {@code SLabel} one side made, the other reads).
 */
@Timeout(120)
class DeployedLabelsTest {

    private static final int RUNS = 5;

    /** The manual's two robots: they calibrate at once (an asynchronous primitive), the agent running main waits for both. */
    static final String CALIBRATE = """
            import SoftWheeledRobot.xml as Rover;
            Rover r1, r2 = newAgent(Rover);
            scalar entry main (true) {
              SLabel all;
              local boolean ok1, ok2;
              all.ok1 = r1.calibrate();
              all.ok2 = r2.calibrate();
              while (!all.isFinished()) {}
              .logln("both calibrated: " + (ok1 && ok2));
            }
            """;

    @Test
    void twoRobotsCalibrateAndTheAgentRunningMainWaitsForBoth() {
        MaslMission mission = MaslMission.fromString("calibrate.masl", CALIBRATE);
        everyDeployment(mission, "r2", run -> run.assertJournal("both calibrated: true\n"));
    }

    /** Every form of the manual's fragment, {@code free} included, on Default's synchronous primitives. */
    @Test
    void everyFormOfALocalLabel() {
        MaslMission mission = MaslMission.fromString("forms.masl", """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                synchronous entry main (true) {
                  SLabel s;
                  LLabel l;
                  local int id = -1;
                  l.a.nop();
                  l.this.nop();
                  l.nop();
                  l.id = b.getProxyID();
                  s.c.nop();
                  while (!l.isFinished() || !isFinished(s)) {}
                  if (isFinished(l)) l.free();
                  .logln(.getProxyID() + ": id " + id + ", remaining " + l.getRemainingInvocations());
                }
                """);
        everyDeployment(mission, "b", run -> run.assertLinesInAnyOrder("0: id 1, remaining 0", "1: id 1, remaining 0",
                "2: id 1, remaining 0"));
    }

    private static void everyDeployment(MaslMission mission, String alone, Consumer<MissionRun> journal) {
        for (MissionPlatform deployment : List.of(DeployedInMemory.everyAgent(), DeployedInMemory.spread(),
                DeployedInMemory.agents(alone))) {
            for (int run = 0; run < RUNS; run++) {
                journal.accept(mission.runOn(deployment));
            }
        }
    }
}
