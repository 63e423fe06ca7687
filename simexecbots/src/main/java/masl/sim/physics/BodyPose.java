package masl.sim.physics;

/**
 * A copy of a body's pose taken between two steps: position and orientation quaternion
 * (w is the real part), in world coordinates. Being a copy, it stays valid while the world steps on.
 */
public record BodyPose(double x, double y, double z, double qw, double qx, double qy, double qz) {

    /** The world direction of the body's local vector (vx, vy, vz). */
    public double[] worldDirection(double vx, double vy, double vz) {
        // v' = v + 2w(u×v) + 2u×(u×v) with u = (qx, qy, qz): the quaternion rotation without a matrix.
        double cx = qy * vz - qz * vy;
        double cy = qz * vx - qx * vz;
        double cz = qx * vy - qy * vx;
        double ccx = qy * cz - qz * cy;
        double ccy = qz * cx - qx * cz;
        double ccz = qx * cy - qy * cx;
        return new double[] {vx + 2 * (qw * cx + ccx), vy + 2 * (qw * cy + ccy), vz + 2 * (qw * cz + ccz)};
    }

    /** Heading in radians: the angle of the body's local +X axis projected on the world XY plane. */
    public double heading() {
        double[] forward = worldDirection(1, 0, 0);
        return Math.atan2(forward[1], forward[0]);
    }
}
