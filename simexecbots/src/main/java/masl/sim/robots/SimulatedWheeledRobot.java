package masl.sim.robots;

import java.util.Set;
import masl.agents.WheeledRobot;
import masl.agents.robots.DifferentialDrive;
import masl.sim.physics.BodyPose;
import masl.sim.physics.PhysicsWorld;
import masl.sim.xode.LoadedModel;
import masl.sim.xode.Pose;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeSource;
import org.ode4j.math.DVector3C;

/**
 * The body of a {@link WheeledRobot} in a {@link PhysicsWorld}: {@code wheeled-robot.xode} loaded
 * with a prefix. Wheel speeds become motor commands; proximity is a ray cast from the hull's edge;
 * odometry integrates the wheel hinges' angular rates after every step, as encoders would; the
 * battery drains with time and wheel speed and, once empty, stops the motors for good.
 *
 * <p>Thread-safe: agents call the {@link DifferentialDrive} methods while the world steps.
 */
public final class SimulatedWheeledRobot implements DifferentialDrive, PhysicsWorld.StepListener {

    /** The body every wheeled robot is made of. */
    public static final XodeSource BODY = XodeSource.resource("masl/agents/robots/wheeled-robot.xode");

    /** Geometry of wheeled-robot.xode. */
    static final double WHEEL_RADIUS = 0.021;
    static final double TRACK = 0.09;
    static final double HULL_HALF_LENGTH = 0.05;
    static final double HULL_HALF_WIDTH = 0.035;
    /** Largest torque (N·m) a wheel motor gives. */
    static final double MOTOR_TORQUE = 0.5;
    /** Range of the proximity rays (m), about a Khepera's. */
    public static final double PROXIMITY_RANGE = 0.2;
    /** Battery drained per simulated second when idle, and per rad/s of each wheel's commanded speed. */
    static final double IDLE_DRAIN = 0.0005;
    static final double SPEED_DRAIN = 0.0001;

    private final PhysicsWorld world;
    private final String chassis;
    private final String leftMotor;
    private final String rightMotor;
    private final Set<String> ownBodies;
    private final double[] hullCentre;
    private double x;
    private double y;
    private double heading;
    private double battery = 1;
    private double commandedLeft;
    private double commandedRight;

    /**
     * Binds to the robot loaded in {@code world} under {@code prefix} (e.g. {@code "k0."}), whose
     * odometry starts at ({@code x}, {@code y}, {@code heading}); registers itself as the world's
     * step listener.
     *
     * @param hullCentre the hull's centre in the chassis body's frame (the body sits at its centre of mass)
     */
    private SimulatedWheeledRobot(PhysicsWorld world, String prefix, double[] hullCentre, double x, double y, double heading) {
        this.world = world;
        this.chassis = prefix + "chassis";
        this.leftMotor = prefix + "leftMotor";
        this.rightMotor = prefix + "rightMotor";
        this.ownBodies = Set.of(chassis, prefix + "leftWheel", prefix + "rightWheel", prefix + "caster");
        this.hullCentre = hullCentre.clone();
        this.x = x;
        this.y = y;
        this.heading = heading;
        world.addStepListener(this);
    }

    /**
     * Loads a robot body into {@code world} under {@code prefix}, standing at ({@code x}, {@code y})
     * on the ground z = 0 and facing {@code heading} (rad from +X), and binds to it.
     */
    public static SimulatedWheeledRobot load(PhysicsWorld world, String prefix, double x, double y, double heading)
            throws XodeException {
        return load(world, BODY, prefix, x, y, heading);
    }

    /**
     * Like {@link #load(PhysicsWorld, String, double, double, double)} with another body, which
     * must name its bodies, hull geom and motors as {@code wheeled-robot.xode} does.
     */
    public static SimulatedWheeledRobot load(PhysicsWorld world, XodeSource body, String prefix, double x, double y,
            double heading) throws XodeException {
        LoadedModel model = world.load(body, prefix, Pose.axisAngle(0, 0, 1, heading).withTranslation(x, y, 0));
        double[] hull = world.withLock(() -> {
            DVector3C offset = model.geom(prefix + "hull").getOffsetPosition();
            return new double[] {offset.get0(), offset.get1(), offset.get2()};
        });
        return new SimulatedWheeledRobot(world, prefix, hull, x, y, heading);
    }

    /** The chassis body's name, whose pose is the robot's. */
    public String chassis() {
        return chassis;
    }

    @Override
    public synchronized void setWheelSpeeds(double left, double right) {
        if (battery <= 0) {
            return;
        }
        commandedLeft = left;
        commandedRight = right;
        world.driveJoint(leftMotor, left, MOTOR_TORQUE);
        world.driveJoint(rightMotor, right, MOTOR_TORQUE);
    }

    @Override
    public double proximity(int sensor) {
        double angle = WheeledRobot.sensorAngle(sensor);
        double cos = Math.cos(angle);
        double sin = Math.sin(angle);
        // From the hull's centre; the part of the ray inside the hull is not measured.
        double edge = Math.min(cos == 0 ? Double.MAX_VALUE : HULL_HALF_LENGTH / Math.abs(cos),
                sin == 0 ? Double.MAX_VALUE : HULL_HALF_WIDTH / Math.abs(sin));
        BodyPose pose = world.bodyPose(chassis);
        double[] offset = pose.worldDirection(hullCentre[0], hullCentre[1], hullCentre[2]);
        double[] origin = {pose.x() + offset[0], pose.y() + offset[1], pose.z() + offset[2]};
        double hit = world.castRay(origin, pose.worldDirection(cos, sin, 0), edge + PROXIMITY_RANGE, ownBodies);
        return Math.max(0, Math.min(PROXIMITY_RANGE, hit - edge));
    }

    @Override
    public synchronized double[] odometry() {
        return new double[] {x, y, heading};
    }

    @Override
    public synchronized double battery() {
        return battery;
    }

    /** A fault: the battery reads 0 from now on and the motors stop. */
    public synchronized void fail() {
        battery = 0;
        stopMotors();
    }

    /** Integrates odometry and drains the battery over the step just taken. */
    @Override
    public synchronized void afterStep(PhysicsWorld stepped) {
        double dt = stepped.settings().stepSize();
        double left = stepped.jointRate(leftMotor) * WHEEL_RADIUS * dt;
        double right = stepped.jointRate(rightMotor) * WHEEL_RADIUS * dt;
        double turn = (right - left) / TRACK;
        double middle = heading + turn / 2;
        x += (left + right) / 2 * Math.cos(middle);
        y += (left + right) / 2 * Math.sin(middle);
        heading = normalise(heading + turn);
        if (battery > 0) {
            battery -= dt * (IDLE_DRAIN + SPEED_DRAIN * (Math.abs(commandedLeft) + Math.abs(commandedRight)));
            if (battery <= 0) {
                battery = 0;
                stopMotors();
            }
        }
    }

    private void stopMotors() {
        commandedLeft = 0;
        commandedRight = 0;
        world.driveJoint(leftMotor, 0, MOTOR_TORQUE);
        world.driveJoint(rightMotor, 0, MOTOR_TORQUE);
    }

    private static double normalise(double angle) {
        return Math.atan2(Math.sin(angle), Math.cos(angle));
    }
}
