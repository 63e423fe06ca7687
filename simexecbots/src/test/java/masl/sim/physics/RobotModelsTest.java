package masl.sim.physics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import masl.sim.xode.Pose;
import masl.sim.xode.XodeException;
import org.junit.jupiter.api.Test;

/** The shipped robot bodies behave like the robots they model. */
class RobotModelsTest {

    /** Wheel radius of wheeled-robot.xode: 5 rad/s is 0.105 m/s. */
    private static final double WHEEL_RADIUS = 0.021;

    private static PhysicsWorld worldWithGround() throws XodeException {
        PhysicsWorld world = new PhysicsWorld(Scenes.settings());
        world.load(Scenes.GROUND, "");
        return world;
    }

    private static double upright(BodyPose pose) {
        return pose.worldDirection(0, 0, 1)[2];
    }

    @Test
    void kheperaWithEqualWheelSpeedsDrivesStraightForward() throws XodeException {
        try (PhysicsWorld world = worldWithGround()) {
            world.load(Scenes.KHEPERA, "k.");
            world.step(50);
            BodyPose start = world.bodyPose("k.chassis");
            world.driveJoint("k.leftMotor", 5, 0.5);
            world.driveJoint("k.rightMotor", 5, 0.5);
            world.step(300);
            BodyPose end = world.bodyPose("k.chassis");
            double dx = end.x() - start.x();
            double dy = end.y() - start.y();
            assertEquals(5 * WHEEL_RADIUS * 3, dx, 0.05, "forward (+X) at about the wheels' rim speed");
            assertTrue(Math.abs(dy) < 0.01 * dx, "straight: sideways drift " + dy + " over " + dx);
            assertEquals(0, end.heading(), 0.02, "heading kept");
            assertTrue(upright(end) > 0.99, "did not tip over");
        }
    }

    @Test
    void kheperaWithOppositeWheelSpeedsTurnsInPlace() throws XodeException {
        try (PhysicsWorld world = worldWithGround()) {
            world.load(Scenes.KHEPERA, "k.");
            world.step(50);
            BodyPose start = world.bodyPose("k.chassis");
            world.driveJoint("k.leftMotor", -3, 0.5);
            world.driveJoint("k.rightMotor", 3, 0.5);
            world.step(50);
            BodyPose end = world.bodyPose("k.chassis");
            // (v_right − v_left) / track = 2 · 3 · 0.021 / 0.09 = 1.4 rad/s, counter-clockwise
            assertEquals(1.4 * 0.5, end.heading() - start.heading(), 0.2);
            assertTrue(Math.hypot(end.x() - start.x(), end.y() - start.y()) < 0.01, "turned in place");
            assertTrue(upright(end) > 0.99, "did not tip over");
        }
    }

    @Test
    void twoPrefixedKheperasAreDistinctRobots() throws XodeException {
        try (PhysicsWorld world = worldWithGround()) {
            world.load(Scenes.KHEPERA, "khepera0.");
            world.load(Scenes.KHEPERA, "khepera1.", Pose.translation(0, 0.5, 0));
            world.step(50);
            BodyPose settled = world.bodyPose("khepera1.chassis");
            world.driveJoint("khepera0.leftMotor", 5, 0.5);
            world.driveJoint("khepera0.rightMotor", 5, 0.5);
            world.step(100);
            BodyPose moving = world.bodyPose("khepera0.chassis");
            BodyPose still = world.bodyPose("khepera1.chassis");
            assertTrue(moving.x() > 0.05, "khepera0 drove");
            assertEquals(settled.x(), still.x(), 0.003, "khepera1 stayed (its caster still settles by a millimetre)");
            assertEquals(0.5, still.y(), 0.002);
            assertNotEquals(moving.y(), still.y());
        }
    }

    @Test
    void maamAtomStandsOnItsLegsAndServosReachTheirTargets() throws XodeException {
        try (PhysicsWorld world = worldWithGround()) {
            world.load(Scenes.MAAM_ATOM, "atom0.");
            for (String leg : new String[] {"front", "back", "left", "right"}) {
                world.command("atom0." + leg + "Swing", new MotorCommand.Servo(0, 10, 3, 2));
                world.command("atom0." + leg + "Lift", new MotorCommand.Servo(0, 10, 3, 2));
            }
            world.step(100);
            BodyPose standing = world.bodyPose("atom0.atom");
            assertTrue(standing.z() > 0.07, "stands on its legs, body at " + standing.z());
            assertTrue(upright(standing) > 0.99);
            world.command("atom0.frontSwing", new MotorCommand.Servo(0.5, 10, 3, 2));
            world.step(100);
            assertEquals(0.5, world.jointPosition("atom0.frontSwing"), 0.05);
            assertEquals(0, world.jointPosition("atom0.backSwing"), 0.05);
        }
    }
}
