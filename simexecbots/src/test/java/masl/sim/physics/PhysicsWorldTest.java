package masl.sim.physics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.NoSuchElementException;
import masl.sim.xode.LoadedModel;
import masl.sim.xode.Pose;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeSource;
import org.junit.jupiter.api.Test;

class PhysicsWorldTest {

    @Test
    void droppedBoxComesToRestOnThePlane() throws XodeException {
        try (PhysicsWorld world = new PhysicsWorld(Scenes.settings())) {
            world.load(Scenes.GROUND, "");
            world.load(XodeSource.text("box.xode", "<xode version=\"1.0r23\"><world><space><body name=\"box\">"
                    + "<transform><position x=\"0\" y=\"0\" z=\"1\"/><rotation><euler x=\"0.2\" y=\"0.1\" z=\"0\"/></rotation></transform>"
                    + "<mass><mass_shape total=\"1\"><box sizex=\"0.2\" sizey=\"0.2\" sizez=\"0.2\"/></mass_shape></mass>"
                    + "<geom><box sizex=\"0.2\" sizey=\"0.2\" sizez=\"0.2\"/></geom></body></space></world></xode>"), "");
            world.step(300);
            BodyPose first = world.bodyPose("box");
            world.step(50);
            BodyPose later = world.bodyPose("box");
            assertEquals(0.1, later.z(), 0.003, "resting on a face, half its height above the floor");
            assertEquals(first.z(), later.z(), 1e-4, "at rest");
            assertEquals(first.x(), later.x(), 1e-4, "at rest");
            assertEquals(3.5, world.simulatedTime(), 1e-9);
        }
    }

    @Test
    void geomsCollideInsideNestedSpaces() throws XodeException {
        try (PhysicsWorld world = new PhysicsWorld(Scenes.settings())) {
            world.load(XodeSource.text("nested.xode", "<xode version=\"1.0r23\"><world><space><space><space>"
                    + "<geom><plane a=\"0\" b=\"0\" c=\"1\" d=\"0\"/></geom>"
                    + "<body name=\"ball\"><transform><position x=\"0\" y=\"0\" z=\"0.5\"/></transform>"
                    + "<mass><mass_shape total=\"1\"><sphere radius=\"0.1\"/></mass_shape></mass>"
                    + "<geom><sphere radius=\"0.1\"/></geom></body>"
                    + "</space></space></space></world></xode>"), "");
            world.step(200);
            assertEquals(0.1, world.bodyPose("ball").z(), 0.003, "the ball rests on the plane of its own nested space");
        }
    }

    @Test
    void raysSenseButDoNotPush() throws XodeException {
        try (PhysicsWorld world = new PhysicsWorld(Scenes.settings())) {
            world.load(Scenes.GROUND, "");
            world.load(XodeSource.text("probe.xode", "<xode version=\"1.0r23\"><world><space><body name=\"probe\">"
                    + "<transform><position x=\"0\" y=\"0\" z=\"0.5\"/></transform>"
                    + "<mass><mass_shape total=\"1\"><sphere radius=\"0.1\"/></mass_shape></mass>"
                    + "<geom><sphere radius=\"0.1\"/></geom>"
                    + "<geom name=\"downRay\"><transform><rotation><euler x=\"180\" y=\"0\" z=\"0\" aformat=\"degrees\"/></rotation>"
                    + "</transform><ray length=\"1\"/></geom>"
                    + "</body></space></world></xode>"), "");
            world.step(200);
            assertEquals(0.1, world.bodyPose("probe").z(), 0.003, "the 1 m ray through the floor does not hold the body up");
        }
    }

    @Test
    void pendulumSwingsWithThePhysicalPeriod() throws XodeException {
        PhysicsSettings settings = Scenes.settings().withStepSize(0.002).withGravity(0, -9.81, 0);
        try (PhysicsWorld world = new PhysicsWorld(settings)) {
            LoadedModel model = world.load(Scenes.PENDULUM, "");
            // The example's anchor (0, 3, 0) is in the bob's frame (xode.md §10.6), so the pivot is
            // at y = 5 and the rod is 3 m long, not 1 m as the example's author may have meant.
            assertEquals(5.0, world.withLock(() -> pivotHeight(model)), 1e-12);
            // a push sideways: about 0.1 rad of amplitude, where the small-angle period holds within 0.1 %
            world.withLock(() -> {
                model.body("bob").setLinearVel(0.3, 0, 0);
                return null;
            });
            double[] crossings = new double[3];
            int found = 0;
            double previousX = 0;
            while (found < 3 && world.simulatedTime() < 15) {
                world.step();
                double x = world.bodyPose("bob").x();
                if (previousX < 0 && x >= 0) {
                    crossings[found++] = world.simulatedTime();
                }
                previousX = x;
            }
            assertEquals(3, found, "the bob keeps swinging");
            // T = 2π √((L² + 2r²/5) / (g L)) for a sphere bob of radius r on a rod of length L.
            double length = 3;
            double expected = 2 * Math.PI * Math.sqrt((length * length + 0.4 * 0.01) / (9.81 * length));
            assertEquals(expected, crossings[1] - crossings[0], expected * 0.02);
            assertEquals(expected, crossings[2] - crossings[1], expected * 0.02);
        }
    }

    private static double pivotHeight(LoadedModel model) {
        org.ode4j.math.DVector3 anchor = new org.ode4j.math.DVector3();
        ((org.ode4j.ode.DHingeJoint) model.joint("pivot")).getAnchor(anchor);
        return anchor.get1();
    }

    @Test
    void lockStepIsDeterministicBitForBitEvenWithWorldsInterleaved() throws XodeException {
        PhysicsSettings settings = Scenes.settings().withSeed(1234);
        try (PhysicsWorld alone = kheperaWorld(settings)) {
            double[] reference = new double[3 * 200];
            for (int i = 0; i < 200; i++) {
                driveStep(alone, i, reference);
            }
            // ode4j's random generator is global: interleaving two worlds must not change either.
            try (PhysicsWorld first = kheperaWorld(settings); PhysicsWorld second = kheperaWorld(settings)) {
                double[] firstTrajectory = new double[3 * 200];
                double[] secondTrajectory = new double[3 * 200];
                for (int i = 0; i < 200; i++) {
                    driveStep(first, i, firstTrajectory);
                    driveStep(second, i, secondTrajectory);
                }
                assertArrayEquals(reference, firstTrajectory);
                assertArrayEquals(reference, secondTrajectory);
            }
        }
    }

    private static PhysicsWorld kheperaWorld(PhysicsSettings settings) throws XodeException {
        PhysicsWorld world = new PhysicsWorld(settings);
        world.load(Scenes.GROUND, "");
        world.load(Scenes.KHEPERA, "k.");
        return world;
    }

    /** Drives a curve, then a turn, and records the chassis's x, y and yaw quaternion part. */
    private static void driveStep(PhysicsWorld world, int step, double[] trajectory) {
        world.driveJoint("k.leftMotor", step < 100 ? 4 : -2, 0.5);
        world.driveJoint("k.rightMotor", 3, 0.5);
        world.step();
        BodyPose pose = world.bodyPose("k.chassis");
        trajectory[3 * step] = pose.x();
        trajectory[3 * step + 1] = pose.y();
        trajectory[3 * step + 2] = pose.qz();
    }

    @Test
    void ownThreadStepsUntilStoppedAndLeavesNoThread() throws Exception {
        PhysicsWorld world = new PhysicsWorld(Scenes.settings());
        try {
            world.load(Scenes.GROUND, "");
            world.start();
            assertTrue(world.isRunning());
            assertThrows(IllegalStateException.class, world::step);
            assertTrue(world.awaitSimulatedTime(0.5, Duration.ofSeconds(20)));
            world.stop();
            assertFalse(world.isRunning());
            assertFalse(physicsThreadAlive(), "no physics thread after stop()");
            long steps = world.stepCount();
            world.step();
            assertEquals(steps + 1, world.stepCount(), "lock-step again after stop()");
        } finally {
            world.close();
        }
    }

    @Test
    void commandsReachARobotDrivenByTheOwnThread() throws Exception {
        try (PhysicsWorld world = new PhysicsWorld(Scenes.settings())) {
            world.load(Scenes.GROUND, "");
            world.load(Scenes.KHEPERA, "k.");
            world.start();
            world.driveJoint("k.leftMotor", 5, 0.5);
            world.driveJoint("k.rightMotor", 5, 0.5);
            double commandedAt = world.simulatedTime();
            assertTrue(world.awaitSimulatedTime(commandedAt + 1.5, Duration.ofSeconds(20)));
            BodyPose pose = world.bodyPose("k.chassis");
            world.stop();
            assertTrue(pose.x() > 0.1, "drove forward while the thread stepped: x = " + pose.x());
        }
    }

    @Test
    void realTimeFactorPacesTheThread() throws Exception {
        try (PhysicsWorld world = new PhysicsWorld(Scenes.settings().withRealTimeFactor(1))) {
            long start = System.nanoTime();
            world.start();
            assertTrue(world.awaitSimulatedTime(0.3, Duration.ofSeconds(20)));
            double wallSeconds = (System.nanoTime() - start) / 1e9;
            world.stop();
            assertTrue(wallSeconds >= 0.25, "0.3 simulated seconds took only " + wallSeconds + " s of wall time");
        }
    }

    @Test
    void closeStopsTheThread() throws Exception {
        PhysicsWorld world = new PhysicsWorld(Scenes.settings());
        world.start();
        world.close();
        assertFalse(physicsThreadAlive());
        assertThrows(IllegalStateException.class, world::step);
    }

    @Test
    void commandsNameLoadedMotorisedJoints() throws XodeException {
        try (PhysicsWorld world = new PhysicsWorld(Scenes.settings())) {
            world.load(Scenes.KHEPERA, "k.");
            assertThrows(NoSuchElementException.class, () -> world.driveJoint("k.noSuchMotor", 1, 1));
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> world.driveJoint("k.casterMount", 1, 1));
            assertTrue(e.getMessage().contains("k.casterMount"));
            assertThrows(NoSuchElementException.class, () -> world.bodyPose("chassis"));
        }
    }

    @Test
    void aNameIsLoadedOnceAndAFailedLoadAddsNothing() throws XodeException {
        try (PhysicsWorld world = new PhysicsWorld(Scenes.settings())) {
            assertThrows(XodeException.class, () -> world.load(XodeSource.text("bad.xode", "<xode/>"), "a."));
            world.load(Scenes.KHEPERA, "a.", Pose.translation(0, 1, 0));
            assertEquals(1.0, world.bodyPose("a.chassis").y(), 1e-9);
            XodeException clash = assertThrows(XodeException.class, () -> world.load(Scenes.KHEPERA, "a."));
            assertTrue(clash.getMessage().startsWith("masl/agents/robots/wheeled-robot.xode:"), clash::getMessage);
            assertTrue(clash.getMessage().contains(": error: <body>: the name 'a.chassis' is already used in the target world"),
                    clash::getMessage);
            assertEquals(java.util.Set.of("a.chassis", "a.leftWheel", "a.rightWheel", "a.caster"), world.bodyNames());
        }
    }

    private static boolean physicsThreadAlive() {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.getName().equals("masl-physics") && t.isAlive());
    }
}
