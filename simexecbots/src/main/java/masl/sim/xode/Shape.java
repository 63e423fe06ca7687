package masl.sim.xode;

/** The collision shape of a geom, as read from XODE (xode.md §6); sizes are full lengths. */
sealed interface Shape {

    record Box(double sizeX, double sizeY, double sizeZ) implements Shape { }

    record Sphere(double radius) implements Shape { }

    /** Along local Z. */
    record Cylinder(double radius, double length) implements Shape { }

    /** ODE's capped cylinder, along local Z; the length excludes the caps. */
    record Capsule(double radius, double length) implements Shape { }

    /** The plane a·x + b·y + c·z = d in world coordinates; never placeable. */
    record Plane(double a, double b, double c, double d) implements Shape { }

    /** Points along local +Z. */
    record Ray(double length) implements Shape { }

    /** Vertex coordinates x,y,z,… and 0-based triangle corner indices. */
    record TriMesh(float[] vertices, int[] indices) implements Shape { }
}
