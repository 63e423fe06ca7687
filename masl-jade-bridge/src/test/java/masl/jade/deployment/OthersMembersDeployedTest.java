package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import masl.jade.Tallies;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * An agent's invocations of another agent's primitives, and its accesses to the other's attributes,
 * run on the other's real object wherever each of them runs: both deployed, in one container or in
 * two, one deployed and the other in the mission's JVM. The journals are those in-process gives.
 */
@Timeout(120)
class OthersMembersDeployedTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    /** In-process, deployed in two containers, in one, the owner alone, the caller alone. */
    private static final List<Map<String, String>> DEPLOYMENTS = List.of(Map.of(),
            Map.of("owner", "c2", "caller", "c3"), Map.of("owner", "c2", "caller", "c2"),
            Map.of("owner", "c2"), Map.of("caller", "c3"));

    @Test
    void aStatefulPrimitiveCountsOnItsAgentWhereverTheCallerRuns() throws Exception {
        for (Map<String, String> deployment : DEPLOYMENTS) {
            assertEquals(Tallies.COUNTS, journal(false, deployment), "deployed: " + deployment);
        }
    }

    @Test
    void anAttributeWrittenByAnotherIsTheOwnersToo() throws Exception {
        for (Map<String, String> deployment : DEPLOYMENTS) {
            assertEquals(Tallies.COUNTS_AND_WRITES, journal(true, deployment), "deployed: " + deployment);
        }
    }

    private static String journal(boolean writes, Map<String, String> deployment) throws InterruptedException {
        InMemoryDeployment.Run run = InMemoryDeployment.run(() -> new Tallies(writes), deployment, TIMEOUT);
        assertTrue(run.outcome().completed(), run.outcome().toString());
        return run.outcome().journal();
    }
}
