package masl.agents;

import masl.agents.robots.DifferentialDrive;

/**
 * A two-wheeled differential robot, Khepera-like (descriptor {@code WheeledRobot.xml}): wheel speed
 * control, eight infra-red proximity sensors, odometry and a battery. The primitives act on a
 * {@link DifferentialDrive} the launcher attaches before the mission starts (the simulator's body,
 * or a real robot's driver). A {@link Robot}: programs written for any robot drive it too.
 *
 * <p>Sensors 0…7 look, relative to the robot's forward direction: 90°, 45°, 10°, −10°, −45°,
 * −90° (left side to right side, as a Khepera's front ring), then 170° and −170° (back).
 */
public class WheeledRobot extends Robot {

    /** Number of proximity sensors. */
    public static final int SENSORS = 8;
    /** Largest wheel speed (rad/s) {@link #setSpeeds} passes on; faster requests are clipped. */
    public static final double MAX_WHEEL_SPEED = 10.0;
    private static final double[] SENSOR_ANGLES = {
        Math.toRadians(90), Math.toRadians(45), Math.toRadians(10), Math.toRadians(-10),
        Math.toRadians(-45), Math.toRadians(-90), Math.toRadians(170), Math.toRadians(-170)};

    private volatile DifferentialDrive drive;

    /**
     * The direction of a sensor in the robot's frame, radians counter-clockwise from forward.
     *
     * @throws IndexOutOfBoundsException unless 0 &le; sensor &lt; {@link #SENSORS}
     */
    public static double sensorAngle(int sensor) {
        return SENSOR_ANGLES[sensor];
    }

    /**
     * Gives the robot its hardware; called once by the launcher, before the mission starts.
     *
     * @throws IllegalStateException when a drive is already attached
     */
    public final void attachHardware(DifferentialDrive hardware) {
        if (hardware == null) {
            throw new NullPointerException("hardware");
        }
        if (drive != null) {
            throw new IllegalStateException("robot hardware already attached");
        }
        drive = hardware;
    }

    /** Sets both wheels' angular speeds (rad/s, positive forward), clipped to ±{@link #MAX_WHEEL_SPEED}. */
    public void setSpeeds(double left, double right) {
        drive().setWheelSpeeds(clip(left), clip(right));
    }

    /** Stops both wheels. */
    @Override
    public void stop() {
        drive().setWheelSpeeds(0, 0);
    }

    /** Distance (m) to the nearest obstacle seen by {@code sensor}, or the sensor's range. */
    public double getProximity(int sensor) {
        return drive().proximity(sensor);
    }

    /** Odometry: x (m) since the start, in the frame of the starting pose's world. */
    @Override
    public double getX() {
        return drive().odometry()[0];
    }

    /** Odometry: y (m). */
    @Override
    public double getY() {
        return drive().odometry()[1];
    }

    /** Odometry: heading (rad, counter-clockwise from world +X). */
    @Override
    public double getHeading() {
        return drive().odometry()[2];
    }

    /** Battery charge in [0, 1]. */
    @Override
    public double getBattery() {
        return drive().battery();
    }

    private DifferentialDrive drive() {
        DifferentialDrive attached = drive;
        if (attached == null) {
            throw new IllegalStateException("robot " + getProxyID() + " has no hardware attached");
        }
        return attached;
    }

    private static double clip(double speed) {
        if (Double.isNaN(speed)) {
            throw new IllegalArgumentException("wheel speed is NaN");
        }
        return Math.max(-MAX_WHEEL_SPEED, Math.min(MAX_WHEEL_SPEED, speed));
    }
}
