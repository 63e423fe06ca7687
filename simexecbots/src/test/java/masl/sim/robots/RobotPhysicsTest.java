package masl.sim.robots;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import masl.agents.MaamAtom;
import masl.sim.physics.BodyPose;
import masl.sim.physics.PhysicsSettings;
import masl.sim.physics.PhysicsWorld;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeSource;
import org.junit.jupiter.api.Test;

/** The physics checks of the simulated robots: each robot moves, turns, falls and latches as its model says. */
class RobotPhysicsTest {

    /** The ground z = 0 and a wall whose face towards the origin is the plane x = {@code 0.5}. */
    static final XodeSource GROUND_AND_WALL = XodeSource.text("arena.xode", """
            <xode version="1.0r23"><world><space>
              <geom name="floor"><plane a="0" b="0" c="1" d="0"/></geom>
              <geom name="wall"><transform><position x="0.55" y="0" z="0.05"/></transform>
                <box sizex="0.1" sizey="1" sizez="0.1"/></geom>
            </space></world></xode>""");
    static final double WALL_FACE_X = 0.5;

    static PhysicsWorld world() throws XodeException {
        PhysicsWorld world = new PhysicsWorld(PhysicsSettings.defaults().withRealTimeFactor(0).withSeed(3));
        world.load(GROUND_AND_WALL, "");
        return world;
    }

    @Test
    void drivingStraightForFiveSecondsCoversWheelSpeedTimesRadiusTimesTime() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedWheeledRobot robot = SimulatedWheeledRobot.load(world, "k.", -1, 0, 0);
            world.step(20);
            BodyPose start = world.bodyPose(robot.chassis());
            double[] odometryStart = robot.odometry();
            double w = 4;
            robot.setWheelSpeeds(w, w);
            world.step(500);
            BodyPose end = world.bodyPose(robot.chassis());
            double expected = w * SimulatedWheeledRobot.WHEEL_RADIUS * 5;
            double travelled = Math.hypot(end.x() - start.x(), end.y() - start.y());
            assertEquals(expected, travelled, 0.1 * expected, "distance");
            double[] odometry = robot.odometry();
            assertEquals(travelled, Math.hypot(odometry[0] - odometryStart[0], odometry[1] - odometryStart[1]),
                    0.1 * expected, "odometry agrees with the true distance");
        }
    }

    @Test
    void turningInPlaceChangesHeadingByTheDifferentialRate() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedWheeledRobot robot = SimulatedWheeledRobot.load(world, "k.", -1, 0, 0.3);
            world.step(20);
            BodyPose start = world.bodyPose(robot.chassis());
            robot.setWheelSpeeds(-3, 3);
            world.step(100);
            BodyPose end = world.bodyPose(robot.chassis());
            double expected = 2 * 3 * SimulatedWheeledRobot.WHEEL_RADIUS / SimulatedWheeledRobot.TRACK * 1.0;
            assertEquals(expected, end.heading() - start.heading(), 0.1 * expected, "heading change");
            assertEquals(0.3 + expected, robot.odometry()[2], 0.1 * expected, "odometry heading");
            assertTrue(Math.hypot(end.x() - start.x(), end.y() - start.y()) < 0.01, "in place");
        }
    }

    @Test
    void proximityRaysReadAWallAtAKnownDistance() throws XodeException {
        try (PhysicsWorld world = world()) {
            double gap = 0.08;
            double x = WALL_FACE_X - gap - SimulatedWheeledRobot.HULL_HALF_LENGTH;
            SimulatedWheeledRobot robot = SimulatedWheeledRobot.load(world, "k.", x, 0, 0);
            world.step(20);
            double along10Degrees = gap / Math.cos(Math.toRadians(10));
            assertEquals(along10Degrees, robot.proximity(2), 0.1 * along10Degrees, "front-left ray");
            assertEquals(along10Degrees, robot.proximity(3), 0.1 * along10Degrees, "front-right ray");
            // The 45° ray leaves the hull through its side, 0.035 / sin 45° from the centre.
            double diagonal = (gap + SimulatedWheeledRobot.HULL_HALF_LENGTH - SimulatedWheeledRobot.HULL_HALF_WIDTH)
                    / Math.cos(Math.toRadians(45));
            assertEquals(diagonal, robot.proximity(1), 0.1 * diagonal, "front-left diagonal ray");
            assertEquals(SimulatedWheeledRobot.PROXIMITY_RANGE, robot.proximity(0), 1e-9, "nothing to the left");
            assertEquals(SimulatedWheeledRobot.PROXIMITY_RANGE, robot.proximity(6), 1e-9, "nothing behind");
        }
    }

    @Test
    void proximityDoesNotSeeTheRobotsOwnWheelsButSeesAnotherRobot() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedWheeledRobot robot = SimulatedWheeledRobot.load(world, "a.", -1, 0, 0);
            SimulatedWheeledRobot.load(world, "b.", -1, 0.2, 0);
            world.step(20);
            // a's left ray meets b's right wheel (centre 0.2 − 0.045, radius 0.021, 9 mm below the ray):
            // 0.155 − √(0.021² − 0.009²) − 0.035 (a's hull) = 0.101 m.
            assertEquals(0.101, robot.proximity(0), 0.0101);
            assertEquals(SimulatedWheeledRobot.PROXIMITY_RANGE, robot.proximity(5), 1e-9);
        }
    }

    @Test
    void anEmptyBatteryStopsTheMotors() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedWheeledRobot robot = SimulatedWheeledRobot.load(world, "k.", -1, 0, 0);
            robot.setWheelSpeeds(5, 5);
            world.step(100);
            assertTrue(robot.battery() < 1 && robot.battery() > 0.99, "drains slowly: " + robot.battery());
            robot.fail();
            world.step(50);
            double stoppedAt = world.bodyPose(robot.chassis()).x();
            robot.setWheelSpeeds(5, 5);
            world.step(100);
            assertEquals(0, robot.battery());
            assertEquals(stoppedAt, world.bodyPose(robot.chassis()).x(), 0.002, "does not move any more");
        }
    }

    @Test
    void aServoReachesItsTargetWithinTwoDegrees() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedAtom atom = SimulatedAtom.load(world, "a.", -1, 0, 0, new SimulatedAtom.Latches());
            world.step(50);
            atom.setServoTarget(MaamAtom.LEFT, MaamAtom.SWING, 0.4);
            atom.setServoTarget(MaamAtom.RIGHT, MaamAtom.LIFT, 0.7);
            world.step(100);
            assertEquals(0.4, atom.servoAngle(MaamAtom.LEFT, MaamAtom.SWING), Math.toRadians(2));
            assertEquals(0.7, atom.servoAngle(MaamAtom.RIGHT, MaamAtom.LIFT), Math.toRadians(2));
            assertEquals(0, atom.servoAngle(MaamAtom.FRONT, MaamAtom.SWING), Math.toRadians(2));
        }
    }

    @Test
    void aLoneAtomStandsOnItsSideFeet() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedAtom atom = SimulatedAtom.load(world, "a.", -1, 0, 0, new SimulatedAtom.Latches());
            world.step(100);
            assertTrue(atom.footOnGround(MaamAtom.LEFT), "standing on its side feet");
            assertTrue(atom.footOnGround(MaamAtom.RIGHT));
            // Two feet are a line: the atom pitches until a latching plate (8 mm higher) touches too.
            assertTrue(world.bodyPose(atom.mainBody()).worldDirection(0, 0, 1)[2] > 0.9, "tilted less than 25°");
        }
    }

    @Test
    void feetOffTheGroundReadSoAfterTheDebounceSteps() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedAtom atom = SimulatedAtom.load(world, "a.", -1, 0, 0, new SimulatedAtom.Latches());
            world.step(50);
            assertTrue(atom.footOnGround(MaamAtom.LEFT) && atom.footOnGround(MaamAtom.RIGHT));
            // 8 N up, more than the atom's weight (about 4.3 N): it leaves the ground.
            for (int i = 0; i < 30; i++) {
                world.addForce(atom.mainBody(), 0, 0, 8);
                world.step();
            }
            for (int leg = 0; leg < MaamAtom.LEGS; leg++) {
                assertFalse(atom.footOnGround(leg), "leg " + leg + " in the air");
            }
            world.step(100);
            assertTrue(atom.footOnGround(MaamAtom.LEFT) && atom.footOnGround(MaamAtom.RIGHT), "landed");
        }
    }

    @Test
    void twoAtomsAttachMoveTogetherThenDetachAndMoveApart() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedAtom.Latches latches = new SimulatedAtom.Latches();
            SimulatedAtom first = SimulatedAtom.load(world, "a0.", -1, 0, 0, latches);
            SimulatedAtom second = SimulatedAtom.load(world, "a1.", -0.88, 0, 0, latches);
            latches.register(0, first);
            latches.register(1, second);
            world.step(50);
            assertTrue(first.attach(MaamAtom.FRONT, 1, MaamAtom.BACK));
            assertTrue(first.attached(MaamAtom.FRONT));
            assertTrue(second.attached(MaamAtom.BACK));
            assertFalse(first.attach(MaamAtom.FRONT, 1, MaamAtom.LEFT), "a foot latches once");

            double latchedGap = gap(first, second);
            pushUp(world, second, 30);
            assertEquals(latchedGap, gap(first, second), 0.003, "latched feet stay together");

            second.detach(MaamAtom.BACK);
            assertFalse(first.attached(MaamAtom.FRONT));
            assertFalse(second.attached(MaamAtom.BACK));
            assertFalse(world.hasJoint("latch:a0.frontLeg+a1.backLeg"));
            pushUp(world, second, 30);
            assertTrue(gap(first, second) > latchedGap + 0.05, "released feet part: " + latchedGap + " -> " + gap(first, second));
        }
    }

    /** Lifts the atom with 6 N, more than its own weight (about 4.3 N) but less than two atoms'. */
    private static void pushUp(PhysicsWorld world, SimulatedAtom atom, int steps) {
        for (int i = 0; i < steps; i++) {
            world.addForce(atom.mainBody(), 0, 0, 6);
            world.step();
        }
    }

    private static double gap(SimulatedAtom first, SimulatedAtom second) {
        double[] a = first.footTip(MaamAtom.FRONT);
        double[] b = second.footTip(MaamAtom.BACK);
        return Math.hypot(Math.hypot(a[0] - b[0], a[1] - b[1]), a[2] - b[2]);
    }

    @Test
    void atomsTooFarApartDoNotAttach() throws XodeException {
        try (PhysicsWorld world = world()) {
            SimulatedAtom.Latches latches = new SimulatedAtom.Latches();
            SimulatedAtom first = SimulatedAtom.load(world, "a0.", -1, 0, 0, latches);
            SimulatedAtom second = SimulatedAtom.load(world, "a1.", -0.7, 0, 0, latches);
            latches.register(0, first);
            latches.register(1, second);
            world.step(20);
            assertFalse(first.attach(MaamAtom.FRONT, 1, MaamAtom.BACK));
            assertFalse(first.attach(MaamAtom.FRONT, 7, MaamAtom.BACK), "no atom 7");
            assertFalse(first.attached(MaamAtom.FRONT));
        }
    }
}
