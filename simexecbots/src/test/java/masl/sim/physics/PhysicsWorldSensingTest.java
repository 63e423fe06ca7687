package masl.sim.physics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeSource;
import org.junit.jupiter.api.Test;

/** What robots sense and do through the world: rays, contacts, latches, listeners, outlines. */
class PhysicsWorldSensingTest {

    /** The ground, a wall face at x = 1 and a 45°-turned static box centred at (0, 3). */
    private static final XodeSource SCENE = XodeSource.text("scene.xode", """
            <xode version="1.0r23"><world><space>
              <geom name="floor"><plane a="0" b="0" c="1" d="0"/></geom>
              <geom name="wall"><transform><position x="1.05" y="0" z="0.5"/></transform>
                <box sizex="0.1" sizey="4" sizez="1"/></geom>
              <geom name="turned"><transform><position x="0" y="3" z="0.5"/>
                <rotation><euler x="0" y="0" z="45" aformat="degrees"/></rotation></transform>
                <box sizex="1" sizey="1" sizez="1"/></geom>
              <body name="ball"><transform><position x="0" y="0" z="0.1"/></transform>
                <mass><mass_shape total="1"><sphere radius="0.1"/></mass_shape></mass>
                <geom><sphere radius="0.1"/></geom></body>
              <body name="cube"><transform><position x="0.5" y="0" z="0.1"/></transform>
                <mass><mass_shape total="1"><box sizex="0.2" sizey="0.2" sizez="0.2"/></mass_shape></mass>
                <geom><box sizex="0.2" sizey="0.2" sizez="0.2"/></geom></body>
            </space></world></xode>""");

    private static PhysicsWorld world() throws XodeException {
        PhysicsWorld world = new PhysicsWorld(Scenes.settings());
        world.load(SCENE, "");
        return world;
    }

    @Test
    void aRayMeetsTheNearestSolidUnlessItsBodyIsIgnored() throws XodeException {
        try (PhysicsWorld world = world()) {
            double[] origin = {0, 0, 0.1};
            double[] east = {2, 0, 0};
            assertEquals(0.4, world.castRay(origin, east, 5, Set.of("ball")), 1e-6, "the cube's near face at x = 0.4");
            assertEquals(1.0, world.castRay(origin, east, 5, Set.of("ball", "cube")), 1e-6, "then the wall");
            assertEquals(Double.POSITIVE_INFINITY, world.castRay(origin, east, 0.3, Set.of("ball")), "beyond its length");
            assertThrows(IllegalArgumentException.class, () -> world.castRay(origin, new double[3], 1, Set.of()));
        }
    }

    @Test
    void contactWithTheGroundIsRememberedForSomeSteps() throws XodeException {
        try (PhysicsWorld world = world()) {
            assertFalse(world.touchesEnvironment("ball", 1), "no step yet");
            world.step(5);
            assertTrue(world.touchesEnvironment("ball", 1), "resting on the floor");
            for (int i = 0; i < 20; i++) {
                world.addForce("ball", 0, 0, 30);
                world.step();
            }
            assertFalse(world.touchesEnvironment("ball", 5), "lifted off: " + world.bodyPose("ball").z());
        }
    }

    @Test
    void aLatchJoinsTwoBodiesUntilDetached() throws XodeException {
        try (PhysicsWorld world = world()) {
            world.attachFixed("latch", "ball", "cube");
            assertTrue(world.hasJoint("latch"));
            assertThrows(IllegalArgumentException.class, () -> world.attachFixed("latch", "ball", "cube"), "name taken");
            assertThrows(IllegalArgumentException.class, () -> world.attachFixed("self", "ball", "ball"));
            for (int i = 0; i < 50; i++) {
                world.addForce("cube", 0, 0, 40);
                world.step();
            }
            assertTrue(world.bodyPose("ball").z() > 0.3, "lifted with the cube");
            assertTrue(world.detach("latch"));
            assertFalse(world.detach("latch"), "gone");
            assertFalse(world.hasJoint("latch"));
        }
    }

    @Test
    void stepListenersAreToldAfterEveryStep() throws XodeException {
        try (PhysicsWorld world = world()) {
            List<Long> steps = new ArrayList<>();
            world.addStepListener(stepped -> steps.add(stepped.stepCount()));
            world.step(3);
            assertEquals(List.of(1L, 2L, 3L), steps);
        }
    }

    @Test
    void staticBoxesHaveTopDownOutlines() throws XodeException {
        try (PhysicsWorld world = world()) {
            List<double[][]> outlines = world.staticBoxOutlines();
            assertEquals(2, outlines.size(), "the wall and the turned box, not the bodies");
            // A space lists its geoms in no set order: tell them apart by where they are.
            double[][] wall = outlines.stream().filter(o -> o[0][0] > 0.5).findFirst().orElseThrow();
            assertArrayEquals(new double[] {1.1, 2}, wall[0], 1e-9);
            assertArrayEquals(new double[] {1.0, -2}, wall[2], 1e-9);
            double half = Math.sqrt(0.5);
            double[][] turned = outlines.stream().filter(o -> o != wall).findFirst().orElseThrow();
            assertArrayEquals(new double[] {0, 3 + half}, turned[0], 1e-9, "a corner on the +Y diagonal");
            assertArrayEquals(new double[] {0, 3 - half}, turned[2], 1e-9);
        }
    }
}
