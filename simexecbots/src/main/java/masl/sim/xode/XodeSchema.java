package masl.sim.xode;

import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;

/**
 * Which attributes and children each XODE 1.0r23 element may have (xode.md §2–§7). Elements
 * inside {@code <ext>} are application data and are never checked.
 */
final class XodeSchema {

    static final Set<String> SHAPES = Set.of("box", "sphere", "cylinder", "cappedCylinder", "capsule", "cone", "plane", "ray", "trimesh");
    static final Set<String> MASS_SHAPES = Set.of("sphere", "box", "cylinder", "cappedCylinder", "capsule");
    static final Set<String> JOINT_TYPES = Set.of("ball", "fixed", "hinge", "hinge2", "slider", "universal", "amotor");
    static final Set<String> AXIS_PARAMETERS = Set.of("LowStop", "HiStop", "Vel", "FMax", "FudgeFactor", "Bounce",
            "CFM", "StopERP", "StopCFM", "SuspensionERP", "SuspensionCFM");

    private static final Set<String> XYZ = Set.of("x", "y", "z");
    private static final Set<String> NAME = Set.of("name");
    private static final Set<String> NONE = Set.of();
    private static final Map<String, Set<String>> ATTRIBUTES = new HashMap<>();
    private static final Map<String, Set<String>> CHILDREN = new HashMap<>();

    static {
        Set<String> scope = Set.of("transform", "body", "geom", "group", "joint", "jointgroup", "space", "ext");
        element("xode", Set.of("version", "name"), Set.of("world", "ext"));
        element("world", NAME, Set.of("transform", "space", "ext"));
        element("space", NAME, scope);
        element("group", NAME, scope);
        element("jointgroup", NAME, Set.of("transform", "joint", "body", "geom", "group", "ext"));
        element("body", Set.of("name", "enabled", "gravitymode"), Set.of("transform", "torque", "force", "finiteRotation",
                "linearVel", "angularVel", "mass", "geom", "body", "joint", "group", "jointgroup", "ext"));
        element("geom", NAME, union(SHAPES, Set.of("transform", "geom", "body", "joint", "jointgroup", "group", "ext")));
        element("joint", NAME, union(JOINT_TYPES, Set.of("link1", "link2", "ext")));
        element("mass", NAME, Set.of("mass_shape", "mass_struct", "transform", "adjust", "mass", "ext"));

        element("transform", Set.of("absolute", "scale"), Set.of("matrix4f", "matrix", "position", "rotation", "ext"));
        element("position", XYZ, NONE);
        element("rotation", NONE, Set.of("euler", "axisangle", "quaternion", "ext"));
        element("euler", Set.of("x", "y", "z", "aformat"), NONE);
        element("axisangle", Set.of("x", "y", "z", "angle", "aformat"), NONE);
        element("quaternion", Set.of("x", "y", "z", "w"), NONE);
        Set<String> matrix4 = matrixAttributes(4);
        element("matrix4f", matrix4, NONE);
        element("matrix", matrix4, NONE);

        for (String vector : new String[] {"torque", "force", "linearVel", "angularVel", "centerGravity", "v"}) {
            element(vector, XYZ, NONE);
        }
        element("finiteRotation", Set.of("mode", "xaxis", "yaxis", "zaxis"), NONE);

        element("mass_shape", Set.of("density", "total"), MASS_SHAPES);
        element("mass_struct", Set.of("total", "mass", "density"), Set.of("centerGravity", "imatrix", "ext"));
        element("imatrix", matrixAttributes(3), NONE);
        element("adjust", Set.of("total"), NONE);

        element("box", Set.of("sizex", "sizey", "sizez"), NONE);
        element("sphere", Set.of("radius"), NONE);
        for (String cylinderLike : new String[] {"cylinder", "cappedCylinder", "capsule", "cone"}) {
            element(cylinderLike, Set.of("radius", "length"), NONE);
        }
        element("plane", Set.of("a", "b", "c", "d"), NONE);
        element("ray", Set.of("length"), NONE);
        element("trimesh", NONE, Set.of("vertices", "triangles", "ext"));
        element("vertices", NONE, Set.of("v", "ext"));
        element("triangles", NONE, Set.of("t", "ext"));
        element("t", Set.of("ia", "ib", "ic"), NONE);

        element("link1", Set.of("body"), NONE);
        element("link2", Set.of("body"), NONE);
        element("anchor", Set.of("x", "y", "z", "absolute"), NONE);
        element("axis", union(Set.of("x", "y", "z", "absolute"), AXIS_PARAMETERS), NONE);
        for (String joint : JOINT_TYPES) {
            element(joint, NONE, joint.equals("fixed") ? Set.of("ext") : Set.of("anchor", "axis", "ext"));
        }
    }

    private XodeSchema() {
    }

    /** Whether XODE defines an element of this name at all. */
    static boolean isKnown(String element) {
        return ATTRIBUTES.containsKey(element) || element.equals("ext");
    }

    /** Whether {@code child} may appear directly inside {@code parent}; ext may appear anywhere. */
    static boolean allowsChild(String parent, String child) {
        return child.equals("ext") || CHILDREN.getOrDefault(parent, NONE).contains(child);
    }

    static boolean allowsAttribute(String element, String attribute) {
        return ATTRIBUTES.getOrDefault(element, NONE).contains(attribute);
    }

    private static void element(String name, Set<String> attributes, Set<String> children) {
        ATTRIBUTES.put(name, attributes);
        CHILDREN.put(name, children);
    }

    private static Set<String> matrixAttributes(int size) {
        Set<String> names = new HashSet<>();
        for (int i = 0; i < size; i++) {
            for (int j = 0; j < size; j++) {
                names.add("m" + i + j);
            }
        }
        return Set.copyOf(names);
    }

    private static Set<String> union(Set<String> a, Set<String> b) {
        Set<String> all = new HashSet<>(a);
        all.addAll(b);
        return Set.copyOf(all);
    }
}
