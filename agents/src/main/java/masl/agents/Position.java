package masl.agents;

import java.util.Objects;

/**
 * A point of the plane, in metres: a utility class robot programs may name and create
 * ({@code new Position(1, 2)}), declared by {@code Robot.xml}. Immutable.
 */
public final class Position {

    private final double x;
    private final double y;

    public Position(double x, double y) {
        this.x = x;
        this.y = y;
    }

    public double getX() {
        return x;
    }

    public double getY() {
        return y;
    }

    /** The straight-line distance to {@code other}, in metres. */
    public double distanceTo(Position other) {
        return Math.hypot(other.x - x, other.y - y);
    }

    @Override
    public boolean equals(Object other) {
        return other instanceof Position that && Double.compare(x, that.x) == 0 && Double.compare(y, that.y) == 0;
    }

    @Override
    public int hashCode() {
        return Objects.hash(x, y);
    }

    /** {@code (x, y)}, as a journal shows it: {@code (1.5, -2.0)}. */
    @Override
    public String toString() {
        return "(" + x + ", " + y + ")";
    }
}
