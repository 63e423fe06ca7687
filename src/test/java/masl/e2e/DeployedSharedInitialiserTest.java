package masl.e2e;

import java.time.Duration;
import java.util.List;
import masl.testing.MaslMission;
import masl.testing.MissionPlatform;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A shared variable's initialiser and update function that make requests of their own to the mission
 * ({@code main.count}, a primitive's call), with the programs deployed: the mission holds the
 * variable's lock while the agent's step in its container runs the code, and performs the code's
 * requests meanwhile, as in-process. Every agent in one container, over two, one alone.
 */
@Timeout(120)
class DeployedSharedInitialiserTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    private static final List<MissionPlatform> DEPLOYMENTS = List.of(DeployedInMemory.everyAgent(),
            DeployedInMemory.spread(), DeployedInMemory.agents("b"));

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
        DEPLOYMENTS.forEach(deployment -> mission.runOn(deployment).assertJournal("n=3\n"));
    }

    @Test
    void anInitialiserCallingAPrimitiveAndAnUpdateReadingTheTeamsSize() {
        MaslMission mission = MaslMission.fromString("total.masl", """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                synchronous entry main (true) {
                  shared int size = .getProxyID() >= 0 ? main.count : -1;
                  shared int total = 0;
                  total = total + main.count;
                  scalar entry report (true) { .logln(size + " agents, total " + total); }
                }
                """).timeout(TIMEOUT);
        DEPLOYMENTS.forEach(deployment -> mission.runOn(deployment).assertJournal("3 agents, total 9\n"));
    }

    /**
     * As {@code missions/mixed-team.masl} reports: an array sized by the team travels to the containers,
     * and each agent's store into its element is made in the mission's array, which the report reads.
     */
    @Test
    void aSharedArraySizedByTheTeamHoldsEveryAgentsElement() {
        MaslMission mission = MaslMission.fromString("reports.masl", """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                synchronous entry main (true) {
                  shared String[] reports = new String[main.count];
                  reports[.getProxyID()] = "agent " + .getProxyID();
                  scalar entry report (true) { .logln(String.join(", ", reports)); }
                }
                """).timeout(TIMEOUT);
        DEPLOYMENTS.forEach(deployment -> mission.runOn(deployment).assertJournal("agent 0, agent 1, agent 2\n"));
    }
}
