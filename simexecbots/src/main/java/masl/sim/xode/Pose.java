package masl.sim.xode;

import org.ode4j.math.DMatrix3;
import org.ode4j.math.DMatrix3C;
import org.ode4j.math.DQuaternion;
import org.ode4j.math.DVector3;
import org.ode4j.ode.DRotation;

/**
 * An immutable rigid transform x ↦ R·x + t (column vectors): a rotation matrix R, stored row by
 * row, and a translation t. XODE frames compose as W = W(parent)·L (xode.md §3).
 */
public final class Pose {

    private static final Pose IDENTITY = new Pose(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, 0, 0, 0);

    private final double[] r;
    private final double tx;
    private final double ty;
    private final double tz;

    private Pose(double[] rowMajorRotation, double tx, double ty, double tz) {
        this.r = rowMajorRotation;
        this.tx = tx;
        this.ty = ty;
        this.tz = tz;
    }

    public static Pose identity() {
        return IDENTITY;
    }

    public static Pose translation(double x, double y, double z) {
        return new Pose(IDENTITY.r, x, y, z);
    }

    /** A pure rotation from a row-major 3×3 matrix, re-orthonormalised (Gram–Schmidt on the columns). */
    public static Pose rotation(double[] rowMajor) {
        return new Pose(orthonormalised(rowMajor), 0, 0, 0);
    }

    /** Rotation by {@code angle} radians about an axis of any non-zero length (right-handed). */
    public static Pose axisAngle(double x, double y, double z, double angle) {
        DMatrix3 m = new DMatrix3();
        DRotation.dRFromAxisAndAngle(m, x, y, z, angle);
        return fromMatrix(m, 0, 0, 0);
    }

    /** Rotation from a quaternion with real part {@code w}; it is normalised first. */
    public static Pose quaternion(double w, double x, double y, double z) {
        DQuaternion q = new DQuaternion(w, x, y, z);
        q.normalize();
        DMatrix3 m = new DMatrix3();
        DRotation.dRfromQ(m, q);
        return fromMatrix(m, 0, 0, 0);
    }

    static Pose fromMatrix(DMatrix3C m, double x, double y, double z) {
        return new Pose(new double[] {
            m.get00(), m.get01(), m.get02(), m.get10(), m.get11(), m.get12(), m.get20(), m.get21(), m.get22()}, x, y, z);
    }

    /** This pose with its translation replaced. */
    public Pose withTranslation(double x, double y, double z) {
        return new Pose(r, x, y, z);
    }

    /** {@code this · other}: apply {@code other} first, then this. */
    public Pose compose(Pose other) {
        double[] m = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m[3 * i + j] = r[3 * i] * other.r[j] + r[3 * i + 1] * other.r[3 + j] + r[3 * i + 2] * other.r[6 + j];
            }
        }
        double[] t = applyToPoint(other.tx, other.ty, other.tz);
        return new Pose(m, t[0], t[1], t[2]);
    }

    public Pose inverse() {
        double[] rt = {r[0], r[3], r[6], r[1], r[4], r[7], r[2], r[5], r[8]};
        Pose rotationOnly = new Pose(rt, 0, 0, 0);
        double[] t = rotationOnly.applyToPoint(-tx, -ty, -tz);
        return new Pose(rt, t[0], t[1], t[2]);
    }

    public double[] applyToPoint(double x, double y, double z) {
        double[] v = rotate(x, y, z);
        return new double[] {v[0] + tx, v[1] + ty, v[2] + tz};
    }

    public double[] rotate(double x, double y, double z) {
        return new double[] {
            r[0] * x + r[1] * y + r[2] * z,
            r[3] * x + r[4] * y + r[5] * z,
            r[6] * x + r[7] * y + r[8] * z};
    }

    public double[] translationVector() {
        return new double[] {tx, ty, tz};
    }

    /** Row-major copy of R. */
    public double[] rotationMatrix() {
        return r.clone();
    }

    public DVector3 toOdePosition() {
        return new DVector3(tx, ty, tz);
    }

    public DMatrix3 toOdeRotation() {
        return new DMatrix3(r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]);
    }

    /** True when R and t differ from the identity by at most {@code tolerance} in every entry. */
    public boolean isIdentity(double tolerance) {
        return isRotationIdentity(tolerance) && Math.abs(tx) <= tolerance && Math.abs(ty) <= tolerance && Math.abs(tz) <= tolerance;
    }

    public boolean isRotationIdentity(double tolerance) {
        for (int i = 0; i < 9; i++) {
            if (Math.abs(r[i] - IDENTITY.r[i]) > tolerance) {
                return false;
            }
        }
        return true;
    }

    private static double[] orthonormalised(double[] m) {
        double[] c0 = {m[0], m[3], m[6]};
        double[] c1 = {m[1], m[4], m[7]};
        normalise(c0);
        double d = dot(c0, c1);
        for (int i = 0; i < 3; i++) {
            c1[i] -= d * c0[i];
        }
        normalise(c1);
        double[] c2 = {c0[1] * c1[2] - c0[2] * c1[1], c0[2] * c1[0] - c0[0] * c1[2], c0[0] * c1[1] - c0[1] * c1[0]};
        return new double[] {c0[0], c1[0], c2[0], c0[1], c1[1], c2[1], c0[2], c1[2], c2[2]};
    }

    private static void normalise(double[] v) {
        double length = Math.sqrt(dot(v, v));
        for (int i = 0; i < 3; i++) {
            v[i] /= length;
        }
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    @Override
    public String toString() {
        return String.format("Pose[t=(%g, %g, %g), R=(%g %g %g; %g %g %g; %g %g %g)]",
                tx, ty, tz, r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]);
    }
}
