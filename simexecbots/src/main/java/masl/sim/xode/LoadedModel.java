package masl.sim.xode;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.Optional;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DJoint;
import org.ode4j.ode.DJointGroup;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DWorld;

/**
 * The ode4j objects created from one XODE document, looked up by their prefixed names
 * ({@code khepera0.chassis}). Unnamed objects exist in the world but cannot be looked up. Each
 * object's {@code getData()} holds its prefixed name (or null).
 *
 * <p>Not thread-safe by itself: the ode4j objects belong to whoever steps their world
 * (see {@code masl.sim.physics.PhysicsWorld} for the rules there).
 */
public final class LoadedModel {

    /** One {@code <world>} of the document with the ode4j world and the space its spaces hang under. */
    public record LoadedWorld(String name, DWorld world, DSpace rootSpace) { }

    private final String sourceName;
    private final String prefix;
    private final List<LoadedWorld> worlds;
    private final Map<String, DBody> bodies;
    private final Map<String, DGeom> geoms;
    private final Map<String, DJoint> joints;
    private final Map<String, DSpace> spaces;
    private final Map<String, DJointGroup> jointGroups;
    private final List<XodeProblem> warnings;

    LoadedModel(String sourceName, String prefix, List<LoadedWorld> worlds, Map<String, DBody> bodies, Map<String, DGeom> geoms,
            Map<String, DJoint> joints, Map<String, DSpace> spaces, Map<String, DJointGroup> jointGroups, List<XodeProblem> warnings) {
        this.sourceName = sourceName;
        this.prefix = prefix;
        this.worlds = List.copyOf(worlds);
        this.bodies = Collections.unmodifiableMap(new LinkedHashMap<>(bodies));
        this.geoms = Collections.unmodifiableMap(new LinkedHashMap<>(geoms));
        this.joints = Collections.unmodifiableMap(new LinkedHashMap<>(joints));
        this.spaces = Collections.unmodifiableMap(new LinkedHashMap<>(spaces));
        this.jointGroups = Collections.unmodifiableMap(new LinkedHashMap<>(jointGroups));
        this.warnings = List.copyOf(warnings);
    }

    public String sourceName() {
        return sourceName;
    }

    /** The prefix put in front of every name of the document, e.g. {@code khepera0.}; may be empty. */
    public String prefix() {
        return prefix;
    }

    /** One entry per {@code <world>}, in document order. */
    public List<LoadedWorld> worlds() {
        return worlds;
    }

    /** @throws NoSuchElementException naming the known bodies when there is no such body */
    public DBody body(String name) {
        return lookup(bodies, name, "body");
    }

    /** @throws NoSuchElementException when there is no such geom */
    public DGeom geom(String name) {
        return lookup(geoms, name, "geom");
    }

    /** @throws NoSuchElementException when there is no such joint */
    public DJoint joint(String name) {
        return lookup(joints, name, "joint");
    }

    /** The joint with that name, if it exists and has the given type. */
    public <T extends DJoint> Optional<T> joint(String name, Class<T> type) {
        DJoint joint = joints.get(name);
        return type.isInstance(joint) ? Optional.of(type.cast(joint)) : Optional.empty();
    }

    public Optional<DSpace> space(String name) {
        return Optional.ofNullable(spaces.get(name));
    }

    public Optional<DJointGroup> jointGroup(String name) {
        return Optional.ofNullable(jointGroups.get(name));
    }

    /** Named bodies in document order (the first of duplicate names wins lookups). */
    public Map<String, DBody> bodies() {
        return bodies;
    }

    public Map<String, DGeom> geoms() {
        return geoms;
    }

    public Map<String, DJoint> joints() {
        return joints;
    }

    /** Warnings of a lenient load (unknown elements, ignored scale…), each with file, line and column. */
    public List<XodeProblem> warnings() {
        return warnings;
    }

    private static <T> T lookup(Map<String, T> map, String name, String kind) {
        T found = map.get(name);
        if (found == null) {
            throw new NoSuchElementException("no " + kind + " named '" + name + "'; known: " + map.keySet());
        }
        return found;
    }
}
