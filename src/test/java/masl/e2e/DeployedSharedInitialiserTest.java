package masl.e2e;

import java.time.Duration;
import java.util.List;
import masl.testing.MaslMission;
import masl.testing.MissionPlatform;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A shared variable's initialiser that the agents' programs evaluate where they run (a member of
 * {@code main}, a primitive's result, an array sized by the team) with the programs deployed: the
 * mission holds the variable's lock while the container runs the initialiser, and the initialiser's
 * own requests to the mission are answered meanwhile, as in-process.
 */
@Timeout(120)
class DeployedSharedInitialiserTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);

    @Test
    void anInitialiserReadingTheTeamsSize() {
        MaslMission mission = MaslMission.fromString("size.masl", """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                synchronous entry main (true) {
                  shared int n = main.count;
                  scalar entry report (true) { .logln("n=" + n); }
                }
                """).timeout(TIMEOUT);
        everyDeployment(mission, "n=3\n");
    }

    private static void everyDeployment(MaslMission mission, String journal) {
        for (MissionPlatform deployment : List.of(DeployedInMemory.everyAgent(), DeployedInMemory.spread(),
                DeployedInMemory.agents("b"))) {
            mission.runOn(deployment).assertJournal(journal);
        }
    }
}
