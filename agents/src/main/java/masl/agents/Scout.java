package masl.agents;

/**
 * A soft wheeled robot with a range finder (descriptor {@code Scout.xml}): {@link #scan} reports
 * how far the obstacle ahead is, and its {@link #moveForward} (a redefinition) stops
 * {@link #SAFETY_MARGIN} short of an obstacle instead of bumping into it.
 */
public class Scout extends SoftWheeledRobot {

    /** How close (m) a scout lets itself come to an obstacle. */
    public static final double SAFETY_MARGIN = 0.5;

    /** Distance (m) to the obstacle straight ahead: the arena's wall. */
    public double scan() {
        return micrometres(distanceToWall(getHeadingDegrees()));
    }

    /** As {@link SoftWheeledRobot#moveForward}, but stopping {@link #SAFETY_MARGIN} short of the wall. */
    @Override
    public synchronized double moveForward(double distance) {
        requireFinite(distance, "distance");
        double direction = distance < 0 ? getHeadingDegrees() + 180 : getHeadingDegrees();
        double room = Math.max(0, distanceToWall(direction) - SAFETY_MARGIN);
        return super.moveForward(Math.copySign(Math.min(Math.abs(distance), room), distance));
    }
}
