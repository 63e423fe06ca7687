package masl.sim.xode;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.ode4j.ode.DMass;

/**
 * Everything an XODE file describes, validated and in world coordinates, but not yet turned into
 * ode4j objects: reading and building are separate so that a file with errors creates nothing.
 */
final class SceneSpec {

    record WorldSpec(String name, XodeElement element) { }

    /** @param parent the enclosing space, or null for a space directly inside its world */
    record SpaceSpec(String name, XodeElement element, WorldSpec world, SpaceSpec parent) { }

    record JointGroupSpec(String name, XodeElement element) { }

    /**
     * @param pose       the ODE pose: the XODE frame, moved to the centre of mass when the mass is off-centre
     * @param mass       centred on the body origin, or null to keep ode4j's default mass
     * @param finiteRotationMode null when not given
     */
    record BodySpec(String name, XodeElement element, WorldSpec world, Pose pose, DMass mass, boolean enabled,
            boolean gravity, double[] force, double[] torque, double[] linearVel, double[] angularVel,
            Integer finiteRotationMode, double[] finiteRotationAxis) { }

    /** @param frame the geom's world frame; @param body null for a static geom */
    record GeomSpec(String name, XodeElement element, Shape shape, Pose frame, BodySpec body, SpaceSpec space) { }

    /**
     * @param direction  world direction, not normalised
     * @param parameters XODE axis parameter name (e.g. {@code LowStop}) to value, in document order
     */
    record AxisSpec(XodeElement element, double[] direction, Map<String, Double> parameters) { }

    /**
     * @param link1Name  prefixed body name of {@code <link1>}, or null
     * @param link2Name  prefixed body name of {@code <link2>}, or null
     * @param enclosing  the nearest enclosing body, or null
     * @param anchor     world point
     */
    record JointSpec(String name, XodeElement element, String type, WorldSpec world, JointGroupSpec group,
            String link1Name, String link2Name, BodySpec enclosing, double[] anchor, List<AxisSpec> axes) { }

    final List<WorldSpec> worlds = new ArrayList<>();
    final List<SpaceSpec> spaces = new ArrayList<>();
    final List<JointGroupSpec> jointGroups = new ArrayList<>();
    final List<BodySpec> bodies = new ArrayList<>();
    final List<GeomSpec> geoms = new ArrayList<>();
    final List<JointSpec> joints = new ArrayList<>();
}
