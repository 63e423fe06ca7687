package masl.sim.xode;

import java.util.List;

/**
 * Reads an element's {@code <transform>} and gives the element's world frame
 * W = W(parent)·L, or W = W(root)·L when {@code absolute="true"} (xode.md §3); W(root) is the
 * identity unless the caller places the document somewhere.
 */
final class TransformReader {

    private static final double DEGREES = Math.PI / 180;

    private final Problems problems;
    private final Attributes attributes;
    private final EulerConvention euler;
    private final Pose root;

    /** @param root the frame of the document root; absolute transforms are measured from it */
    TransformReader(Problems problems, Attributes attributes, EulerConvention euler, Pose root) {
        this.problems = problems;
        this.attributes = attributes;
        this.euler = euler;
        this.root = root;
    }

    /** The world frame of {@code element}, whose enclosing frame is {@code parentFrame}. */
    Pose worldFrame(XodeElement element, Pose parentFrame) {
        List<XodeElement> transforms = element.children("transform");
        if (transforms.isEmpty()) {
            return parentFrame;
        }
        if (transforms.size() > 1) {
            problems.error(transforms.get(1), "<" + element.name() + "> may hold only one <transform>");
        }
        XodeElement transform = transforms.get(0);
        Pose local = local(transform);
        return attributes.bool(transform, "absolute", false) ? root.compose(local) : parentFrame.compose(local);
    }

    private Pose local(XodeElement transform) {
        double scale = attributes.optional(transform, "scale", 1);
        if (scale != 1) {
            // ODE cannot scale rigid bodies (xode.md §10.3).
            problems.warning(transform, "scale " + scale + " is ignored: rigid bodies cannot be scaled");
        }
        List<XodeElement> matrices = transform.children("matrix4f");
        matrices = matrices.isEmpty() ? transform.children("matrix") : matrices;
        boolean hasParts = transform.child("position").isPresent() || transform.child("rotation").isPresent();
        if (!matrices.isEmpty()) {
            if (hasParts || matrices.size() > 1 || transform.children("matrix").size() + transform.children("matrix4f").size() > 1) {
                problems.error(transform, "a transform holds either one matrix or a position and/or a rotation");
            }
            return matrix(matrices.get(0));
        }
        double[] t = {0, 0, 0};
        List<XodeElement> positions = transform.children("position");
        if (positions.size() > 1) {
            problems.error(positions.get(1), "a transform holds at most one <position>");
        }
        if (!positions.isEmpty()) {
            t = vector(positions.get(0));
        }
        List<XodeElement> rotations = transform.children("rotation");
        if (rotations.size() > 1) {
            problems.error(rotations.get(1), "a transform holds at most one <rotation>");
        }
        Pose rotation = rotations.isEmpty() ? Pose.identity() : rotation(rotations.get(0));
        return rotation.withTranslation(t[0], t[1], t[2]);
    }

    private Pose rotation(XodeElement rotation) {
        List<XodeElement> forms = rotation.children().stream()
                .filter(c -> c.name().equals("euler") || c.name().equals("axisangle") || c.name().equals("quaternion"))
                .toList();
        if (forms.size() != 1) {
            problems.error(rotation, "a rotation holds exactly one of <euler>, <axisangle> or <quaternion>, found " + forms.size());
            return Pose.identity();
        }
        XodeElement form = forms.get(0);
        switch (form.name()) {
            case "euler":
                return euler(form);
            case "axisangle": {
                double[] axis = vector(form);
                double angle = attributes.required(form, "angle") * angleUnit(form);
                if (axis[0] == 0 && axis[1] == 0 && axis[2] == 0) {
                    problems.error(form, "the rotation axis must not be (0, 0, 0)");
                    return Pose.identity();
                }
                return Pose.axisAngle(axis[0], axis[1], axis[2], angle);
            }
            default: {
                double[] v = vector(form);
                double w = attributes.required(form, "w");
                if (w == 0 && v[0] == 0 && v[1] == 0 && v[2] == 0) {
                    problems.error(form, "a quaternion must not be (0, 0, 0, 0)");
                    return Pose.identity();
                }
                return Pose.quaternion(w, v[0], v[1], v[2]);
            }
        }
    }

    private Pose euler(XodeElement form) {
        double unit = angleUnit(form);
        double[] a = vector(form);
        double sign = euler == EulerConvention.PYODE_COMPATIBLE ? -1 : 1;
        return Pose.axisAngle(1, 0, 0, sign * a[0] * unit)
                .compose(Pose.axisAngle(0, 1, 0, sign * a[1] * unit))
                .compose(Pose.axisAngle(0, 0, 1, sign * a[2] * unit));
    }

    private double angleUnit(XodeElement form) {
        return attributes.choice(form, "aformat", "radians", "radians", "degrees").equals("degrees") ? DEGREES : 1;
    }

    /**
     * Column-vector matrices carry the translation in m03–m23; row-vector ones (PyODE's tests) in
     * m30–m32, recognisable by a last column of (0,0,0,1): those are transposed (xode.md §10.2).
     */
    private Pose matrix(XodeElement matrix) {
        double[][] m = new double[4][4];
        for (int i = 0; i < 4; i++) {
            for (int j = 0; j < 4; j++) {
                m[i][j] = attributes.required(matrix, "m" + i + j);
            }
        }
        boolean bottomRowAffine = m[3][0] == 0 && m[3][1] == 0 && m[3][2] == 0 && m[3][3] == 1;
        boolean lastColumnAffine = m[0][3] == 0 && m[1][3] == 0 && m[2][3] == 0 && m[3][3] == 1;
        if (!bottomRowAffine && lastColumnAffine) {
            double[][] transposed = new double[4][4];
            for (int i = 0; i < 4; i++) {
                for (int j = 0; j < 4; j++) {
                    transposed[i][j] = m[j][i];
                }
            }
            m = transposed;
        } else if (!bottomRowAffine) {
            problems.error(matrix, "not a rigid transform: neither the bottom row nor the last column is (0, 0, 0, 1)");
            return Pose.identity();
        }
        double[] rotation = {m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]};
        if (determinant(rotation) <= 1e-9) {
            problems.error(matrix, "the 3×3 part is not a rotation (its determinant is not positive)");
            return Pose.identity();
        }
        return Pose.rotation(rotation).withTranslation(m[0][3], m[1][3], m[2][3]);
    }

    private double[] vector(XodeElement element) {
        return new double[] {
            attributes.required(element, "x"), attributes.required(element, "y"), attributes.required(element, "z")};
    }

    private static double determinant(double[] m) {
        return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
    }
}
