package masl.sim.xode;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import masl.sim.xode.SceneSpec.AxisSpec;
import masl.sim.xode.SceneSpec.BodySpec;
import masl.sim.xode.SceneSpec.JointGroupSpec;
import masl.sim.xode.SceneSpec.JointSpec;
import masl.sim.xode.SceneSpec.WorldSpec;

/**
 * Reads a {@code <joint>} (xode.md §7): its type, links, anchor and axes with their parameters,
 * converted to world coordinates. Link names are resolved later, once every body is known.
 */
final class JointReader {

    private final Problems problems;
    private final Attributes attributes;
    private final String prefix;
    private final Pose root;

    /** @param root the frame absolute anchors and axes are measured from */
    JointReader(Problems problems, Attributes attributes, String prefix, Pose root) {
        this.problems = problems;
        this.attributes = attributes;
        this.prefix = prefix;
        this.root = root;
    }

    /** @return the joint, or null when it cannot be built */
    JointSpec read(XodeElement joint, String name, Pose frame, WorldSpec world, JointGroupSpec group, BodySpec enclosing) {
        List<XodeElement> types = joint.children().stream().filter(c -> XodeSchema.JOINT_TYPES.contains(c.name())).toList();
        if (types.size() != 1) {
            problems.error(joint, "a joint holds exactly one joint type (ball, fixed, hinge, hinge2, slider, universal, amotor), found "
                    + types.size());
            return null;
        }
        XodeElement type = types.get(0);
        String link1 = link(joint, "link1");
        String link2 = link(joint, "link2");
        double[] anchor = anchor(type, frame);
        List<XodeElement> axisElements = type.children("axis");
        if (!axisCountFits(type.name(), axisElements.size())) {
            problems.error(type, "a " + type.name() + " joint needs " + expectedAxes(type.name()) + ", found " + axisElements.size());
            return null;
        }
        List<AxisSpec> axes = new ArrayList<>();
        for (int i = 0; i < axisElements.size(); i++) {
            axes.add(axis(axisElements.get(i), type.name(), i, frame));
        }
        return new JointSpec(name, joint, type.name(), world, group, link1, link2, enclosing, anchor, axes);
    }

    private String link(XodeElement joint, String which) {
        List<XodeElement> links = joint.children(which);
        if (links.size() > 1) {
            problems.error(links.get(1), "a joint holds at most one <" + which + ">");
        }
        if (links.isEmpty()) {
            return null;
        }
        XodeElement link = links.get(0);
        if (link.attribute("body").isEmpty()) {
            problems.error(link, "missing required attribute 'body'");
            return null;
        }
        return prefix + link.attribute("body").get();
    }

    /** A missing anchor is the parent frame's origin (xode.md §10.9); absolute="true" means the document root's frame. */
    private double[] anchor(XodeElement type, Pose frame) {
        List<XodeElement> anchors = type.children("anchor");
        if (anchors.size() > 1) {
            problems.error(anchors.get(1), "a joint holds at most one <anchor>");
        }
        if (!anchors.isEmpty() && type.name().equals("slider")) {
            problems.error(anchors.get(0), "a slider joint has no anchor");
        }
        if (anchors.isEmpty()) {
            return frame.translationVector();
        }
        XodeElement anchor = anchors.get(0);
        double x = attributes.required(anchor, "x");
        double y = attributes.required(anchor, "y");
        double z = attributes.required(anchor, "z");
        return attributes.bool(anchor, "absolute", false) ? root.applyToPoint(x, y, z) : frame.applyToPoint(x, y, z);
    }

    private AxisSpec axis(XodeElement axis, String type, int index, Pose frame) {
        double x = attributes.required(axis, "x");
        double y = attributes.required(axis, "y");
        double z = attributes.required(axis, "z");
        if (x == 0 && y == 0 && z == 0) {
            problems.error(axis, "the axis direction must not be (0, 0, 0)");
            x = 1;
        }
        double[] direction = attributes.bool(axis, "absolute", false) ? root.rotate(x, y, z) : frame.rotate(x, y, z);
        Map<String, Double> parameters = new LinkedHashMap<>();
        for (String parameter : axis.attributes().keySet()) {
            if (!XodeSchema.AXIS_PARAMETERS.contains(parameter)) {
                continue;
            }
            double value = attributes.required(axis, parameter);
            if (parameter.startsWith("Suspension") && !(type.equals("hinge2") && index == 0)) {
                problems.error(axis, parameter + " exists only on the first axis of a hinge2 joint");
            } else if (parameter.equals("FMax") && value < 0) {
                problems.warning(axis, "FMax must not be negative; ode4j would ignore " + value);
            } else if (parameter.equals("FudgeFactor") && (value < 0 || value > 1)) {
                problems.warning(axis, "FudgeFactor must lie in [0, 1]; ode4j would ignore " + value);
            } else {
                parameters.put(parameter, value);
            }
        }
        return new AxisSpec(axis, direction, parameters);
    }

    private static boolean axisCountFits(String type, int count) {
        switch (type) {
            case "hinge":
            case "slider":
                return count == 1;
            case "hinge2":
            case "universal":
                return count == 2;
            case "amotor":
                return count >= 1 && count <= 3;
            default:
                return count == 0;
        }
    }

    private static String expectedAxes(String type) {
        switch (type) {
            case "hinge":
            case "slider":
                return "exactly 1 <axis>";
            case "hinge2":
            case "universal":
                return "exactly 2 <axis> elements";
            case "amotor":
                return "1 to 3 <axis> elements";
            default:
                return "no <axis>";
        }
    }
}
