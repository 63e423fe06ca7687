package masl.agents.robots;

/**
 * The hardware of a two-wheeled differential robot as {@link masl.agents.WheeledRobot} drives it:
 * a simulated body (SimExecBots) or a driver for a real robot implements it. Units are SI: metres,
 * radians, seconds; the robot's frame has +X forward, +Y to the left, headings counter-clockwise.
 *
 * <p>Implementations are called from agent threads while the robot moves: they must be
 * thread-safe, and no method may block waiting for the robot (commands take effect later; reads
 * return the latest known value).
 */
public interface DifferentialDrive {

    /** Sets the wheels' angular speeds (rad/s, positive rolls forward), in force until changed. */
    void setWheelSpeeds(double left, double right);

    /**
     * The distance (m) from the robot's hull to the nearest obstacle along infra-red ray
     * {@code sensor} (0 … {@link masl.agents.WheeledRobot#SENSORS}−1), or the sensor's range when
     * nothing is that close.
     *
     * @throws IndexOutOfBoundsException for a sensor the robot does not have
     */
    double proximity(int sensor);

    /** Dead-reckoned pose from the wheel encoders since the start: x (m), y (m), heading (rad). */
    double[] odometry();

    /** Battery charge, 1 when full, 0 when empty; an empty battery stops the motors. */
    double battery();
}
