package masl.sim.xode;

import java.util.List;
import java.util.Set;
import masl.sim.xode.SceneSpec.BodySpec;
import masl.sim.xode.SceneSpec.GeomSpec;
import masl.sim.xode.SceneSpec.JointGroupSpec;
import masl.sim.xode.SceneSpec.JointSpec;
import masl.sim.xode.SceneSpec.SpaceSpec;
import masl.sim.xode.SceneSpec.WorldSpec;
import org.ode4j.ode.DMass;

/**
 * Turns a checked element tree into a {@link SceneSpec}: walks the document computing every
 * element's world frame, reads bodies, geoms and joints, then resolves joint links in a second
 * pass so that a joint may name a body defined after it (xode.md §10.8).
 */
final class SceneReader {

    /** Where an element sits: its enclosing frame and the nearest enclosing world, space, body and joint group. */
    private record Scope(Pose frame, WorldSpec world, SpaceSpec space, BodySpec body, JointGroupSpec group) {
        Scope withFrame(Pose newFrame) {
            return new Scope(newFrame, world, space, body, group);
        }
    }

    private static final double TOLERANCE = 1e-12;

    private final Problems problems;
    private final Pose root;
    private final Attributes attributes;
    private final TransformReader transforms;
    private final MassReader masses;
    private final ShapeReader shapes;
    private final JointReader joints;
    private final NameRegistry names;
    private final SceneSpec scene = new SceneSpec();

    /**
     * @param root       where the document's root is placed in the world
     * @param takenNames prefixed names already used in the target world
     */
    SceneReader(Problems problems, LoadOptions options, String prefix, Pose root, Set<String> takenNames) {
        this.problems = problems;
        this.root = root;
        this.attributes = new Attributes(problems);
        this.transforms = new TransformReader(problems, attributes, options.euler(), root);
        this.masses = new MassReader(problems, attributes, transforms);
        this.shapes = new ShapeReader(problems, attributes);
        this.joints = new JointReader(problems, attributes, prefix, root);
        this.names = new NameRegistry(problems, prefix, takenNames);
    }

    SceneSpec read(XodeElement document) {
        checkVersion(document);
        for (XodeElement world : document.children("world")) {
            readWorld(world);
        }
        if (scene.worlds.isEmpty()) {
            problems.error(document, "the document holds no <world>");
        }
        names.reportDuplicates(new LinkChecker(problems, names).check(scene.bodies, scene.joints));
        return scene;
    }

    private void checkVersion(XodeElement document) {
        String version = document.attribute("version").orElse(null);
        if (version == null) {
            problems.error(document, "missing required attribute 'version'");
        } else if (!version.equals("1.0r23")) {
            if (version.matches("1\\.0r\\d+")) {
                problems.notice(document, "version " + version + " read as 1.0r23");
            } else {
                problems.warning(document, "version " + version + " is not XODE 1.0; read as 1.0r23");
            }
        }
    }

    private void readWorld(XodeElement element) {
        WorldSpec world = new WorldSpec(name(element), element);
        scene.worlds.add(world);
        Scope scope = new Scope(transforms.worldFrame(element, root), world, null, null, null);
        for (XodeElement space : element.children("space")) {
            readSpace(space, scope);
        }
    }

    private void readSpace(XodeElement element, Scope outer) {
        SpaceSpec space = new SpaceSpec(name(element), element, outer.world(), outer.space());
        scene.spaces.add(space);
        Pose frame = transforms.worldFrame(element, outer.frame());
        readScopeChildren(element, new Scope(frame, outer.world(), space, outer.body(), outer.group()));
    }

    /** The children a space, group, jointgroup, body or geom may share: bodies, geoms, joints, groups… */
    private void readScopeChildren(XodeElement element, Scope scope) {
        for (XodeElement child : element.children()) {
            switch (child.name()) {
                case "body" -> readBody(child, scope);
                case "geom" -> readGeom(child, scope);
                case "joint" -> readJoint(child, scope);
                case "group" -> {
                    name(child);
                    readScopeChildren(child, scope.withFrame(transforms.worldFrame(child, scope.frame())));
                }
                case "jointgroup" -> readJointGroup(child, scope);
                case "space" -> readSpace(child, scope);
                default -> {
                    // transform, mass, shapes and the like belong to the element itself, read elsewhere.
                }
            }
        }
    }

    private void readJointGroup(XodeElement element, Scope scope) {
        JointGroupSpec group = new JointGroupSpec(name(element), element);
        scene.jointGroups.add(group);
        Pose frame = transforms.worldFrame(element, scope.frame());
        readScopeChildren(element, new Scope(frame, scope.world(), scope.space(), scope.body(), group));
    }

    private void readBody(XodeElement element, Scope scope) {
        String name = name(element);
        Pose frame = transforms.worldFrame(element, scope.frame());
        List<XodeElement> massElements = element.children("mass");
        if (massElements.size() > 1) {
            problems.error(massElements.get(1), "a body holds at most one <mass>; nest masses inside it to combine them");
        }
        DMass mass = massElements.isEmpty() ? null : masses.read(massElements.get(0), frame);
        Pose pose = frame;
        if (mass != null) {
            if (mass.getMass() <= 0 || !mass.check()) {
                problems.error(massElements.get(0), "the mass is not physically valid (total " + mass.getMass()
                        + "); give a shape with a positive size and density, or a positive total");
                mass = null;
            } else {
                pose = centred(frame, mass);
            }
        }
        XodeElement finite = element.child("finiteRotation").orElse(null);
        BodySpec body = new BodySpec(name, element, scope.world(), pose, mass,
                attributes.bool(element, "enabled", true),
                attributes.choice(element, "gravitymode", "1", "1", "0").equals("1"),
                vector(element, "force"), vector(element, "torque"), vector(element, "linearVel"), vector(element, "angularVel"),
                finite == null ? null : Integer.valueOf(attributes.choice(finite, "mode", "0", "0", "1")),
                finite == null ? null : new double[] {
                    attributes.optional(finite, "xaxis", 0), attributes.optional(finite, "yaxis", 0), attributes.optional(finite, "zaxis", 0)});
        scene.bodies.add(body);
        readScopeChildren(element, new Scope(frame, scope.world(), scope.space(), body, scope.group()));
    }

    /**
     * ode4j refuses a mass whose centre is not the body origin, so the body is moved to the centre
     * of mass and the mass shifted back (xode.md §9); geom offsets are later taken from this pose.
     */
    private static Pose centred(Pose frame, DMass mass) {
        double cx = mass.getC().get0();
        double cy = mass.getC().get1();
        double cz = mass.getC().get2();
        if (cx == 0 && cy == 0 && cz == 0) {
            return frame;
        }
        mass.translate(-cx, -cy, -cz);
        double[] centre = frame.applyToPoint(cx, cy, cz);
        return frame.withTranslation(centre[0], centre[1], centre[2]);
    }

    private void readGeom(XodeElement element, Scope scope) {
        String name = name(element);
        Pose frame = transforms.worldFrame(element, scope.frame());
        List<XodeElement> shapeElements = element.children().stream().filter(c -> XodeSchema.SHAPES.contains(c.name())).toList();
        if (shapeElements.size() != 1) {
            problems.error(element, "a geom holds exactly one shape, found " + shapeElements.size());
        } else {
            Shape shape = shapes.read(shapeElements.get(0));
            if (shape instanceof Shape.Plane plane) {
                shape = worldPlane(shapeElements.get(0), plane, frame, scope.body() != null);
                scene.geoms.add(new GeomSpec(name, element, shape, Pose.identity(), null, scope.space()));
            } else if (shape != null) {
                scene.geoms.add(new GeomSpec(name, element, shape, frame, scope.body(), scope.space()));
            }
        }
        readScopeChildren(element, scope.withFrame(frame));
    }

    /** Planes are never placeable: keep them static and move their equation into the world (xode.md §10.11). */
    private Shape.Plane worldPlane(XodeElement element, Shape.Plane plane, Pose frame, boolean underBody) {
        if (underBody) {
            problems.warning(element, "a plane cannot move with a body: it stays static where the body starts");
        }
        if (frame.isIdentity(TOLERANCE)) {
            return plane;
        }
        problems.warning(element, "the plane equation is transformed by the enclosing transforms");
        double[] n = frame.rotate(plane.a(), plane.b(), plane.c());
        double[] t = frame.translationVector();
        return new Shape.Plane(n[0], n[1], n[2], plane.d() + n[0] * t[0] + n[1] * t[1] + n[2] * t[2]);
    }

    private void readJoint(XodeElement element, Scope scope) {
        String name = name(element);
        JointSpec joint = joints.read(element, name, scope.frame(), scope.world(), scope.group(), scope.body());
        if (joint != null) {
            scene.joints.add(joint);
        }
    }

    private String name(XodeElement element) {
        return names.register(element);
    }

    private double[] vector(XodeElement body, String childName) {
        List<XodeElement> vectors = body.children(childName);
        if (vectors.size() > 1) {
            problems.error(vectors.get(1), "a body holds at most one <" + childName + ">");
        }
        if (vectors.isEmpty()) {
            return null;
        }
        XodeElement v = vectors.get(0);
        return new double[] {attributes.required(v, "x"), attributes.required(v, "y"), attributes.required(v, "z")};
    }
}
