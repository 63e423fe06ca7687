package masl.sim.xode;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import masl.sim.xode.SceneSpec.AxisSpec;
import masl.sim.xode.SceneSpec.BodySpec;
import masl.sim.xode.SceneSpec.GeomSpec;
import masl.sim.xode.SceneSpec.JointGroupSpec;
import masl.sim.xode.SceneSpec.JointSpec;
import masl.sim.xode.SceneSpec.SpaceSpec;
import masl.sim.xode.SceneSpec.WorldSpec;
import org.ode4j.math.DVector3;
import org.ode4j.ode.DAMotorJoint;
import org.ode4j.ode.DBallJoint;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DFixedJoint;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DHinge2Joint;
import org.ode4j.ode.DHingeJoint;
import org.ode4j.ode.DJoint;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DSliderJoint;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DTriMeshData;
import org.ode4j.ode.DUniversalJoint;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeHelper;

/**
 * Creates the ode4j objects of a validated {@link SceneSpec} in the order of xode.md §9: worlds,
 * spaces and joint groups; bodies with final poses and masses; geoms; then joints, whose anchors
 * and axes are captured against the bodies' poses.
 */
final class SceneBuilder {

    private final Map<WorldSpec, DWorld> worlds = new IdentityHashMap<>();
    private final Map<WorldSpec, DSpace> rootSpaces = new IdentityHashMap<>();
    private final Map<SpaceSpec, DSpace> spaces = new IdentityHashMap<>();
    private final Map<JointGroupSpec, DJointGroup> jointGroups = new IdentityHashMap<>();
    private final Map<BodySpec, DBody> bodies = new IdentityHashMap<>();
    private final Map<String, DBody> bodiesByName = new LinkedHashMap<>();
    private final Map<String, BodySpec> bodySpecsByName = new LinkedHashMap<>();
    private final Map<String, DGeom> geomsByName = new LinkedHashMap<>();
    private final Map<String, DJoint> jointsByName = new LinkedHashMap<>();
    private final Map<String, DSpace> spacesByName = new LinkedHashMap<>();
    private final Map<String, DJointGroup> jointGroupsByName = new LinkedHashMap<>();
    private final List<LoadedModel.LoadedWorld> loadedWorlds = new ArrayList<>();

    LoadedModel build(SceneSpec scene, LoadTarget target, String sourceName, String prefix, List<XodeProblem> warnings) {
        DWorld sharedWorld = target.createsWorlds() ? null : target.worldFor();
        DSpace sharedSpace = target.createsWorlds() ? null : target.rootSpaceFor();
        for (WorldSpec world : scene.worlds) {
            DWorld dWorld = sharedWorld != null ? sharedWorld : target.worldFor();
            DSpace root = sharedSpace != null ? sharedSpace : target.rootSpaceFor();
            worlds.put(world, dWorld);
            rootSpaces.put(world, root);
            loadedWorlds.add(new LoadedModel.LoadedWorld(world.name(), dWorld, root));
        }
        for (SpaceSpec space : scene.spaces) {
            DSpace parent = space.parent() == null ? rootSpaces.get(space.world()) : spaces.get(space.parent());
            DSpace created = OdeHelper.createHashSpace(parent);
            created.setData(space.name());
            spaces.put(space, created);
            putFirst(spacesByName, space.name(), created);
        }
        for (JointGroupSpec group : scene.jointGroups) {
            DJointGroup created = OdeHelper.createJointGroup();
            jointGroups.put(group, created);
            putFirst(jointGroupsByName, group.name(), created);
        }
        scene.bodies.forEach(this::createBody);
        scene.geoms.forEach(this::createGeom);
        scene.joints.forEach(this::createJoint);
        return new LoadedModel(sourceName, prefix, loadedWorlds, bodiesByName, geomsByName, jointsByName, spacesByName,
                jointGroupsByName, warnings);
    }

    private void createBody(BodySpec spec) {
        DBody body = OdeHelper.createBody(worlds.get(spec.world()));
        body.setData(spec.name());
        body.setPosition(spec.pose().toOdePosition());
        body.setRotation(spec.pose().toOdeRotation());
        if (spec.mass() != null) {
            body.setMass(spec.mass());
        }
        if (spec.force() != null) {
            body.setForce(new DVector3(spec.force()));
        }
        if (spec.torque() != null) {
            body.setTorque(new DVector3(spec.torque()));
        }
        if (spec.linearVel() != null) {
            body.setLinearVel(new DVector3(spec.linearVel()));
        }
        if (spec.angularVel() != null) {
            body.setAngularVel(new DVector3(spec.angularVel()));
        }
        if (spec.finiteRotationMode() != null) {
            body.setFiniteRotationMode(spec.finiteRotationMode() == 1);
            body.setFiniteRotationAxis(new DVector3(spec.finiteRotationAxis()));
        }
        if (!spec.gravity()) {
            body.setGravityMode(false);
        }
        if (!spec.enabled()) {
            body.disable();
        }
        bodies.put(spec, body);
        putFirst(bodiesByName, spec.name(), body);
        putFirst(bodySpecsByName, spec.name(), spec);
    }

    private void createGeom(GeomSpec spec) {
        DSpace space = spaces.get(spec.space());
        DGeom geom = createShape(spec.shape(), space);
        geom.setData(spec.name());
        if (!(spec.shape() instanceof Shape.Plane)) {
            if (spec.body() != null) {
                geom.setBody(bodies.get(spec.body()));
                Pose offset = spec.body().pose().inverse().compose(spec.frame());
                geom.setOffsetPosition(offset.toOdePosition());
                geom.setOffsetRotation(offset.toOdeRotation());
            } else {
                geom.setPosition(spec.frame().toOdePosition());
                geom.setRotation(spec.frame().toOdeRotation());
            }
        }
        putFirst(geomsByName, spec.name(), geom);
    }

    private static DGeom createShape(Shape shape, DSpace space) {
        if (shape instanceof Shape.Box box) {
            return OdeHelper.createBox(space, box.sizeX(), box.sizeY(), box.sizeZ());
        } else if (shape instanceof Shape.Sphere sphere) {
            return OdeHelper.createSphere(space, sphere.radius());
        } else if (shape instanceof Shape.Cylinder cylinder) {
            return OdeHelper.createCylinder(space, cylinder.radius(), cylinder.length());
        } else if (shape instanceof Shape.Capsule capsule) {
            return OdeHelper.createCapsule(space, capsule.radius(), capsule.length());
        } else if (shape instanceof Shape.Plane plane) {
            return OdeHelper.createPlane(space, plane.a(), plane.b(), plane.c(), plane.d());
        } else if (shape instanceof Shape.Ray ray) {
            return OdeHelper.createRay(space, ray.length());
        }
        Shape.TriMesh mesh = (Shape.TriMesh) shape;
        DTriMeshData data = OdeHelper.createTriMeshData();
        data.build(mesh.vertices(), mesh.indices());
        data.preprocess();
        return OdeHelper.createTriMesh(space, data, null, null, null);
    }

    private void createJoint(JointSpec spec) {
        DWorld world = worlds.get(spec.world());
        DJointGroup group = spec.group() == null ? null : jointGroups.get(spec.group());
        BodySpec[] ends = JointEnds.resolve(bodySpec(spec.link1Name()), spec.link1Name() != null,
                bodySpec(spec.link2Name()), spec.link2Name() != null, spec.enclosing());
        DJoint joint = newJoint(spec.type(), world, group);
        joint.setData(spec.name());
        joint.attach(ends[0] == null ? null : bodies.get(ends[0]), ends[1] == null ? null : bodies.get(ends[1]));
        placeAnchorAndAxes(joint, spec);
        List<AxisSpec> axes = spec.axes();
        for (int i = 0; i < axes.size(); i++) {
            for (Map.Entry<String, Double> parameter : axes.get(i).parameters().entrySet()) {
                joint.setParam(AxisParameters.odeParameter(parameter.getKey(), i), parameter.getValue());
            }
        }
        putFirst(jointsByName, spec.name(), joint);
    }

    private BodySpec bodySpec(String name) {
        return name == null ? null : bodySpecsByName.get(name);
    }

    private static DJoint newJoint(String type, DWorld world, DJointGroup group) {
        switch (type) {
            case "ball": return OdeHelper.createBallJoint(world, group);
            case "fixed": return OdeHelper.createFixedJoint(world, group);
            case "hinge": return OdeHelper.createHingeJoint(world, group);
            case "hinge2": return OdeHelper.createHinge2Joint(world, group);
            case "slider": return OdeHelper.createSliderJoint(world, group);
            case "universal": return OdeHelper.createUniversalJoint(world, group);
            default: return OdeHelper.createAMotorJoint(world, group);
        }
    }

    private static void placeAnchorAndAxes(DJoint joint, JointSpec spec) {
        DVector3 anchor = new DVector3(spec.anchor());
        List<AxisSpec> axes = spec.axes();
        if (joint instanceof DBallJoint ball) {
            ball.setAnchor(anchor);
        } else if (joint instanceof DFixedJoint fixed) {
            fixed.setFixed();
        } else if (joint instanceof DHingeJoint hinge) {
            hinge.setAnchor(anchor);
            hinge.setAxis(new DVector3(axes.get(0).direction()));
        } else if (joint instanceof DHinge2Joint hinge2) {
            hinge2.setAnchor(anchor);
            hinge2.setAxes(new DVector3(axes.get(0).direction()), new DVector3(axes.get(1).direction()));
        } else if (joint instanceof DSliderJoint slider) {
            slider.setAxis(new DVector3(axes.get(0).direction()));
        } else if (joint instanceof DUniversalJoint universal) {
            universal.setAnchor(anchor);
            universal.setAxis1(new DVector3(axes.get(0).direction()));
            universal.setAxis2(new DVector3(axes.get(1).direction()));
        } else {
            DAMotorJoint motor = (DAMotorJoint) joint;
            motor.setMode(DAMotorJoint.AMotorMode.dAMotorUser);
            motor.setNumAxes(axes.size());
            for (int i = 0; i < axes.size(); i++) {
                // relative-orientation mode 0: the axis is fixed in the global frame (xode.md §9).
                motor.setAxis(i, 0, new DVector3(axes.get(i).direction()));
            }
        }
    }

    private static <T> void putFirst(Map<String, T> map, String name, T value) {
        if (name != null) {
            map.putIfAbsent(name, value);
        }
    }
}
