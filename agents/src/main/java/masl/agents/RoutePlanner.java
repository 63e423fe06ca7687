package masl.agents;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * A software agent that plans robots' routes around the obstacles they report (descriptor
 * {@code RoutePlanner.xml}, the mixed team of missions/planner-team.masl). An obstacle is known as a disc: a robot reports
 * where its ray hit something, and the planner assumes a body of up to {@link #DEPTH} behind that
 * point and keeps {@link #RADIUS} around its centre free. A route goes straight to the goal unless
 * it crosses a disc; then it side-steps the disc by two way-points (the first disc it meets first),
 * and goes on from there the same way.
 *
 * <p>Routes are strings {@code "x1,y1,x2,y2,…"} (metres, the last point the goal) so that they
 * travel as event messages too. Thread-safe: robots may call it while it serves others.
 */
public class RoutePlanner extends Default {

    /** How far behind a reported hit the planner puts an obstacle's centre (m). */
    public static final double DEPTH = 0.1;
    /** The radius kept free around an obstacle's centre (m): half a 20 cm box's diagonal and half a robot. */
    public static final double RADIUS = 0.25;
    /** How far beside a disc the detour passes (m). */
    private static final double MARGIN = 0.05;
    /** Detours planned for one route at most: a route never loops between obstacles. */
    private static final int MAX_DETOURS = 4;

    private final List<double[]> obstacles = new ArrayList<>();

    /**
     * A robot at ({@code fromX}, {@code fromY}) saw something at ({@code hitX}, {@code hitY}).
     * A hit inside a known obstacle's disc adds nothing.
     */
    public synchronized void addObstacle(double fromX, double fromY, double hitX, double hitY) {
        double length = Math.hypot(hitX - fromX, hitY - fromY);
        double[] centre = length == 0 ? new double[] {hitX, hitY}
                : new double[] {hitX + DEPTH * (hitX - fromX) / length, hitY + DEPTH * (hitY - fromY) / length};
        for (double[] known : obstacles) {
            if (Math.hypot(known[0] - centre[0], known[1] - centre[1]) < RADIUS) {
                return;
            }
        }
        obstacles.add(centre);
    }

    /** Number of obstacles known. */
    public synchronized int getObstacleCount() {
        return obstacles.size();
    }

    /** The way-points from ({@code fromX}, {@code fromY}) to the goal ({@code toX}, {@code toY}). */
    public synchronized String route(double fromX, double fromY, double toX, double toY) {
        List<double[]> points = new ArrayList<>();
        double[] from = {fromX, fromY};
        double[] goal = {toX, toY};
        for (int detours = 0; detours < MAX_DETOURS; detours++) {
            double[] obstacle = firstObstacleOn(from, goal);
            if (obstacle == null) {
                break;
            }
            double[][] sideStep = sideStep(from, goal, obstacle);
            points.add(sideStep[0]);
            points.add(sideStep[1]);
            from = sideStep[1];
        }
        points.add(goal);
        StringBuilder text = new StringBuilder();
        for (double[] point : points) {
            text.append(text.length() == 0 ? "" : ",").append(String.format(Locale.ROOT, "%.3f,%.3f", point[0], point[1]));
        }
        return text.toString();
    }

    /** The obstacle whose disc the segment crosses nearest to {@code from}, or null. */
    private double[] firstObstacleOn(double[] from, double[] to) {
        double[] first = null;
        double nearest = Double.MAX_VALUE;
        for (double[] obstacle : obstacles) {
            double along = projection(from, to, obstacle);
            double[] closest = pointAt(from, to, Math.max(0, Math.min(1, along)));
            if (Math.hypot(closest[0] - obstacle[0], closest[1] - obstacle[1]) < RADIUS && along < nearest) {
                nearest = along;
                first = obstacle;
            }
        }
        return first;
    }

    /**
     * Two way-points that pass the obstacle on the side of the line from→to it does not lie on
     * (the left when it lies on the line): level with the disc's near edge, then with its far edge.
     */
    private static double[][] sideStep(double[] from, double[] to, double[] obstacle) {
        double length = Math.hypot(to[0] - from[0], to[1] - from[1]);
        double dx = (to[0] - from[0]) / length;
        double dy = (to[1] - from[1]) / length;
        double cross = dx * (obstacle[1] - from[1]) - dy * (obstacle[0] - from[0]);
        double side = cross > 0 ? -1 : 1;
        double nx = -dy * side * (RADIUS + MARGIN);
        double ny = dx * side * (RADIUS + MARGIN);
        return new double[][] {
            {obstacle[0] - dx * RADIUS + nx, obstacle[1] - dy * RADIUS + ny},
            {obstacle[0] + dx * RADIUS + nx, obstacle[1] + dy * RADIUS + ny}};
    }

    private static double projection(double[] from, double[] to, double[] point) {
        double dx = to[0] - from[0];
        double dy = to[1] - from[1];
        double squared = dx * dx + dy * dy;
        return squared == 0 ? 0 : ((point[0] - from[0]) * dx + (point[1] - from[1]) * dy) / squared;
    }

    private static double[] pointAt(double[] from, double[] to, double t) {
        return new double[] {from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1])};
    }
}
