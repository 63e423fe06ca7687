package masl.agents;

/**
 * The common supertype of the robot types (descriptor {@code Robot.xml}): what a program written
 * for any robot may ask of it, a pose, a battery and {@code stop}. Its subtypes give these a body:
 * {@link WheeledRobot} (a drive the simulator or a real robot provides), {@link SoftWheeledRobot}
 * and {@link Scout} (kinematics in software, for missions run without simulation).
 *
 * <p>On its own, a {@code Robot} is a robot without a drive: it stays at the origin facing +X,
 * its battery full, and {@code stop} has nothing to stop.
 */
public class Robot extends Default {

    /** Stops every motion of the robot. */
    public void stop() {
        // No drive, nothing moving: a robot of this type is always stopped.
    }

    /** x (m) in the world's frame. */
    public double getX() {
        return 0;
    }

    /** y (m) in the world's frame. */
    public double getY() {
        return 0;
    }

    /** Heading (rad, counter-clockwise from world +X). */
    public double getHeading() {
        return 0;
    }

    /** Battery charge in [0, 1]. */
    public double getBattery() {
        return 1;
    }

    /** Where the robot is: {@code (getX(), getY())}, so that subtypes need only give those two. */
    public Position getPosition() {
        return new Position(getX(), getY());
    }
}
