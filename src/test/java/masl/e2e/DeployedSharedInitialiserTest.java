package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import masl.runtime.MissionOutcome;
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
     * As {@code missions/mixed-team.masl} reports: an array's value does not travel between the mission
     * and a container, so the agents fail at once, saying so, rather than waiting for the timeout.
     */
    @Test
    void aSharedArraySizedByTheTeamFailsSayingArraysDoNotTravel() {
        MaslMission mission = MaslMission.fromString("reports.masl", """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                synchronous entry main (true) {
                  shared String[] reports = new String[main.count];
                  reports[.getProxyID()] = "agent " + .getProxyID();
                }
                """).timeout(TIMEOUT);
        MissionOutcome outcome = mission.runOn(DeployedInMemory.everyAgent()).outcome();
        assertTrue(outcome.status() == MissionOutcome.Status.FAILED, outcome.toString());
        Throwable cause = outcome.failure().orElseThrow();
        while (cause.getCause() != null) {
            cause = cause.getCause();
        }
        assertTrue(String.valueOf(cause.getMessage()).contains("String[] value cannot travel"), cause.toString());
    }
}
