package masl.jade.placement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** {@code --deploy}: named agents, {@code *} spread over containers with {@code +}; mistakes with their positions. */
class DeploymentTest {

    private static final List<String> TEAM = List.of("leader", "w1", "w2", "w3");

    @Test
    void namedAgentsGoWhereNamedInDeclarationOrder() {
        Map<String, String> deployment = Deployment.parse("w2=c3, leader=c2", TEAM, Set.of(), Set.of());
        assertEquals(List.of("leader", "w2"), List.copyOf(deployment.keySet()));
        assertEquals(Map.of("leader", "c2", "w2", "c3"), deployment);
        assertEquals(List.of("c2", "c3"), Deployment.containersOf(deployment));
    }

    @Test
    void starSpreadsTheAgentsNotNamedOverItsContainersInTurn() {
        assertEquals(Map.of("leader", "c2", "w1", "c3", "w2", "c2", "w3", "c3"),
                Deployment.parse("*=c2+c3", TEAM, Set.of(), Set.of()));
        assertEquals(Map.of("leader", "c9", "w1", "c2", "w2", "c3", "w3", "c2"),
                Deployment.parse("leader=c9,*=c2+c3", TEAM, Set.of(), Set.of()));
    }

    @Test
    void starLeavesThePlacedAgentsHere() {
        assertEquals(Map.of("leader", "c2", "w2", "c2", "w3", "c2"), Deployment.parse("*=c2", TEAM, Set.of("w1"), Set.of()));
    }

    @Test
    void starLeavesTheAgentsExternalFipaAgentsStandForHere() {
        assertEquals(Map.of("leader", "c2", "w2", "c3"), Deployment.parse("*=c2+c3", TEAM, Set.of("w3"), Set.of("w1")));
        assertEquals("--deploy:1:7: error: w1 stands for an external FIPA agent (its type has <Fipa>): its program"
                + " runs here, its primitives are that agent's; it cannot be deployed",
                assertThrows(IllegalArgumentException.class,
                        () -> Deployment.parse("w2=c2,w1=c3", TEAM, Set.of(), Set.of("w1"))).getMessage());
    }

    @Test
    void mistakesArePositioned() {
        assertEquals("--deploy:1:11: error: expected AGENT=CONTAINER or *=CONTAINER+CONTAINER, got 'w2'",
                message("leader=c2,w2"));
        assertEquals("--deploy:1:4: error: 'c 2' is not a container name (letters, digits, '_', '.', '-')",
                message("w1=c 2"));
        assertEquals("--deploy:1:6: error: '' is not a container name (letters, digits, '_', '.', '-')",
                message("*=c2++c3"));
        assertEquals("--deploy:1:7: error: w1 is deployed twice", message("w1=c2,w1=c3"));
        assertEquals("--deploy:1:6: error: * is given twice", message("*=c2,*=c3"));
        assertEquals("--deploy:1:1: error: w9 is not an agent of the program (it declares leader, w1, w2, w3)",
                message("w9=c2"));
        assertEquals("--deploy:1:4: error: w1 is one agent: give it one container, or spread * over several",
                message("w1=c2+c3"));
        assertEquals("--deploy:1:1: error: w1 is placed with --place: its program runs here, its body there;"
                + " deploy it or place it, not both",
                assertThrows(IllegalArgumentException.class,
                        () -> Deployment.parse("w1=c2", TEAM, Set.of("w1"), Set.of())).getMessage());
    }

    private static String message(String option) {
        return assertThrows(IllegalArgumentException.class, () -> Deployment.parse(option, TEAM, Set.of(), Set.of())).getMessage();
    }
}
