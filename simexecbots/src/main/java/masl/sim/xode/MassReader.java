package masl.sim.xode;

import java.util.List;
import org.ode4j.ode.DMass;
import org.ode4j.ode.OdeHelper;

/**
 * Evaluates a {@code <mass>} into an ode4j mass expressed in its parent's frame (xode.md §5), in
 * the order decided there: shape or struct, then nested masses added, then this mass's
 * transform, then {@code adjust}.
 */
final class MassReader {

    /** ODE's mass functions take the long axis as an index: 3 is local Z, where XODE puts it. */
    private static final int Z_AXIS = 3;

    private final Problems problems;
    private final Attributes attributes;
    private final TransformReader transforms;

    MassReader(Problems problems, Attributes attributes, TransformReader transforms) {
        this.problems = problems;
        this.attributes = attributes;
        this.transforms = transforms;
    }

    /** The mass of {@code mass}, whose parent's world frame is {@code parentFrame}. */
    DMass read(XodeElement mass, Pose parentFrame) {
        Pose frame = transforms.worldFrame(mass, parentFrame);
        DMass result = OdeHelper.createMass();
        result.setZero();
        List<XodeElement> sources = mass.children().stream()
                .filter(c -> c.name().equals("mass_shape") || c.name().equals("mass_struct")).toList();
        if (sources.size() > 1) {
            problems.error(sources.get(1), "a mass holds at most one <mass_shape> or <mass_struct>");
        }
        if (!sources.isEmpty()) {
            XodeElement source = sources.get(0);
            if (source.name().equals("mass_shape")) {
                shapeMass(source, result);
            } else {
                structMass(source, result);
            }
        }
        for (XodeElement nested : mass.children("mass")) {
            result.add(read(nested, frame));
        }
        Pose local = parentFrame.inverse().compose(frame);
        result.rotate(local.toOdeRotation());
        double[] t = local.translationVector();
        result.translate(t[0], t[1], t[2]);
        List<XodeElement> adjusts = mass.children("adjust");
        if (adjusts.size() > 1) {
            problems.error(adjusts.get(1), "a mass holds at most one <adjust>");
        }
        if (!adjusts.isEmpty()) {
            double total = attributes.positive(adjusts.get(0), "total");
            if (result.getMass() > 0) {
                result.adjust(total);
            } else {
                problems.error(adjusts.get(0), "cannot adjust a mass that is zero");
            }
        }
        return result;
    }

    private void shapeMass(XodeElement massShape, DMass into) {
        List<XodeElement> shapes = massShape.children().stream().filter(c -> XodeSchema.MASS_SHAPES.contains(c.name())).toList();
        if (shapes.size() != 1) {
            problems.error(massShape, "a mass_shape holds exactly one of <sphere>, <box>, <cylinder> or <cappedCylinder>, found " + shapes.size());
            return;
        }
        boolean hasTotal = massShape.attribute("total").isPresent();
        double amount;
        if (hasTotal) {
            amount = attributes.positive(massShape, "total");
        } else if (massShape.attribute("density").isPresent()) {
            amount = attributes.positive(massShape, "density");
        } else {
            problems.warning(massShape, "neither density nor total given: density 1 is used");
            amount = 1;
        }
        XodeElement shape = shapes.get(0);
        switch (shape.name()) {
            case "sphere": {
                double radius = attributes.positive(shape, "radius");
                if (hasTotal) {
                    into.setSphereTotal(amount, radius);
                } else {
                    into.setSphere(amount, radius);
                }
                break;
            }
            case "box": {
                double x = attributes.positive(shape, "sizex");
                double y = attributes.positive(shape, "sizey");
                double z = attributes.positive(shape, "sizez");
                if (hasTotal) {
                    into.setBoxTotal(amount, x, y, z);
                } else {
                    into.setBox(amount, x, y, z);
                }
                break;
            }
            case "cylinder": {
                double radius = attributes.positive(shape, "radius");
                double length = attributes.positive(shape, "length");
                if (hasTotal) {
                    into.setCylinderTotal(amount, Z_AXIS, radius, length);
                } else {
                    into.setCylinder(amount, Z_AXIS, radius, length);
                }
                break;
            }
            default: {
                double radius = attributes.positive(shape, "radius");
                double length = attributes.positive(shape, "length");
                if (hasTotal) {
                    into.setCapsuleTotal(amount, Z_AXIS, radius, length);
                } else {
                    into.setCapsule(amount, Z_AXIS, radius, length);
                }
            }
        }
    }

    /** xode.md §10.10: mass_struct is unverified, so both {@code total} and {@code mass} name the total. */
    private void structMass(XodeElement struct, DMass into) {
        String totalName = struct.attribute("total").isPresent() ? "total" : "mass";
        if (struct.attribute(totalName).isEmpty()) {
            problems.error(struct, "missing required attribute 'total'");
            return;
        }
        double total = attributes.positive(struct, totalName);
        double[] c = {0, 0, 0};
        if (struct.child("centerGravity").isPresent()) {
            XodeElement g = struct.child("centerGravity").get();
            c = new double[] {attributes.required(g, "x"), attributes.required(g, "y"), attributes.required(g, "z")};
        }
        XodeElement inertia = struct.child("imatrix").orElse(null);
        if (inertia == null) {
            problems.error(struct, "a mass_struct needs an <imatrix>");
            return;
        }
        double[][] m = new double[3][3];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m[i][j] = attributes.required(inertia, "m" + i + j);
            }
        }
        if (m[0][1] != m[1][0] || m[0][2] != m[2][0] || m[1][2] != m[2][1]) {
            problems.error(inertia, "the inertia matrix must be symmetric");
            return;
        }
        into.setParameters(total, c[0], c[1], c[2], m[0][0], m[1][1], m[2][2], m[0][1], m[0][2], m[1][2]);
    }
}
