package masl.sim.xode;

import java.util.List;

/** Reads a geom's shape element (xode.md §6); returns null when the shape cannot be used. */
final class ShapeReader {

    private final Problems problems;
    private final Attributes attributes;

    ShapeReader(Problems problems, Attributes attributes) {
        this.problems = problems;
        this.attributes = attributes;
    }

    Shape read(XodeElement shape) {
        switch (shape.name()) {
            case "box":
                return new Shape.Box(attributes.positive(shape, "sizex"), attributes.positive(shape, "sizey"),
                        attributes.positive(shape, "sizez"));
            case "sphere":
                return new Shape.Sphere(attributes.positive(shape, "radius"));
            case "cylinder":
                return new Shape.Cylinder(attributes.positive(shape, "radius"), attributes.positive(shape, "length"));
            case "cappedCylinder":
            case "capsule":
                return new Shape.Capsule(attributes.positive(shape, "radius"), attributes.positive(shape, "length"));
            case "plane":
                return plane(shape);
            case "ray":
                return new Shape.Ray(attributes.positive(shape, "length"));
            case "trimesh":
                return triMesh(shape);
            default:
                // cone: known to XODE readers but absent from ode4j (xode.md §10.12).
                problems.warning(shape, "ode4j has no cone: this geom is skipped");
                return null;
        }
    }

    private Shape plane(XodeElement shape) {
        double a = attributes.required(shape, "a");
        double b = attributes.required(shape, "b");
        double c = attributes.required(shape, "c");
        double d = attributes.required(shape, "d");
        if (a == 0 && b == 0 && c == 0 && shape.attribute("a").isPresent() && shape.attribute("b").isPresent()
                && shape.attribute("c").isPresent()) {
            problems.error(shape, "the plane normal (a, b, c) must not be (0, 0, 0)");
            return null;
        }
        return new Shape.Plane(a, b, c, d);
    }

    /** Indices are 1-based (PyODE) unless some index is 0, then all are 0-based (xode.md §10.5). */
    private Shape triMesh(XodeElement shape) {
        List<XodeElement> vertexLists = shape.children("vertices");
        List<XodeElement> triangleLists = shape.children("triangles");
        if (vertexLists.size() != 1 || triangleLists.size() != 1) {
            problems.error(shape, "a trimesh holds exactly one <vertices> and one <triangles>");
            return null;
        }
        List<XodeElement> vs = vertexLists.get(0).children("v");
        List<XodeElement> ts = triangleLists.get(0).children("t");
        if (vs.size() < 3 || ts.isEmpty()) {
            problems.error(shape, "a trimesh needs at least 3 vertices and 1 triangle");
            return null;
        }
        float[] vertices = new float[3 * vs.size()];
        for (int i = 0; i < vs.size(); i++) {
            vertices[3 * i] = (float) attributes.required(vs.get(i), "x");
            vertices[3 * i + 1] = (float) attributes.required(vs.get(i), "y");
            vertices[3 * i + 2] = (float) attributes.required(vs.get(i), "z");
        }
        int[] indices = new int[3 * ts.size()];
        boolean zeroBased = false;
        for (int i = 0; i < ts.size(); i++) {
            indices[3 * i] = attributes.index(ts.get(i), "ia");
            indices[3 * i + 1] = attributes.index(ts.get(i), "ib");
            indices[3 * i + 2] = attributes.index(ts.get(i), "ic");
            zeroBased |= indices[3 * i] == 0 || indices[3 * i + 1] == 0 || indices[3 * i + 2] == 0;
        }
        if (zeroBased) {
            problems.warning(shape, "a triangle index is 0, so all indices are read as 0-based");
        }
        int base = zeroBased ? 0 : 1;
        for (int i = 0; i < indices.length; i++) {
            indices[i] -= base;
            if (indices[i] >= vs.size()) {
                problems.error(ts.get(i / 3), "vertex index " + (indices[i] + base) + " is out of range (" + vs.size() + " vertices)");
                return null;
            }
        }
        return new Shape.TriMesh(vertices, indices);
    }
}
