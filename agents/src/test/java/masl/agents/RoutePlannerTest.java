package masl.agents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.descriptor.Primitive;
import org.junit.jupiter.api.Test;

/** The route planner of the mixed-team mission: its descriptor, and routes around reported obstacles. */
class RoutePlannerTest {

    @Test
    void descriptorDeclaresObstaclesAndRoutes() {
        DescriptorLoader loader = new DescriptorLoader(AgentPath.parse(""));
        AgentType type = loader.load(loader.agentPath().find("RoutePlanner.xml", null).orElseThrow());
        assertEquals("masl.agents.RoutePlanner", type.fullClassName());
        assertEquals(List.of("getProxyID", "nop", "log", "logln", "sleep", "addObstacle", "getObstacleCount", "route"),
                type.primitives().stream().map(Primitive::name).toList());
    }

    @Test
    void withoutObstaclesARouteIsTheGoal() {
        assertEquals("1.600,0.800", new RoutePlanner().route(0, 0.8, 1.6, 0.8));
    }

    @Test
    void aReportedObstacleIsSideSteppedOnTheSideItDoesNotLieOn() {
        RoutePlanner planner = new RoutePlanner();
        planner.addObstacle(0.5, 0, 0.6, 0.02);   // slightly left of the line y = 0: pass on the right

        double[] route = points(planner.route(0.5, 0, 1.6, 0));

        assertEquals(6, route.length);
        double[] centre = {0.6 + 0.1 * 0.1 / Math.hypot(0.1, 0.02), 0.02 + 0.1 * 0.02 / Math.hypot(0.1, 0.02)};
        for (int point = 0; point < 2; point++) {
            assertTrue(route[2 * point + 1] < 0, "way-point " + point + " on the right");
            assertTrue(Math.hypot(route[2 * point] - centre[0], route[2 * point + 1] - centre[1]) > RoutePlanner.RADIUS);
        }
        assertEquals(1.6, route[4], 1e-9);
        assertEquals(0, route[5], 1e-9);
    }

    @Test
    void aHitInsideAKnownObstacleAddsNone() {
        RoutePlanner planner = new RoutePlanner();
        planner.addObstacle(0.5, 0, 0.6, 0);
        planner.addObstacle(0.45, 0.05, 0.62, 0.03);
        assertEquals(1, planner.getObstacleCount());
        assertEquals("1.600,0.800", planner.route(0, 0.8, 1.6, 0.8));
    }

    private static double[] points(String route) {
        return Arrays.stream(route.split(",")).mapToDouble(Double::parseDouble).toArray();
    }
}
