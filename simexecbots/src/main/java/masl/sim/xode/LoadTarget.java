package masl.sim.xode;

import java.util.Objects;
import java.util.Set;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DWorld;
import org.ode4j.ode.OdeHelper;

/**
 * Where the objects of a document go. A stand-alone file gets a new ode4j world and root hash
 * space per {@code <world>} (xode.md §10.13); a robot file loaded into a running simulation puts
 * every {@code <world>} into the simulation's world, each {@code <space>} becoming a child space.
 */
public final class LoadTarget {

    private final DWorld world;
    private final DSpace space;
    private final Pose placement;
    private final Set<String> takenNames;

    private LoadTarget(DWorld world, DSpace space, Pose placement, Set<String> takenNames) {
        this.world = world;
        this.space = space;
        this.placement = Objects.requireNonNull(placement);
        this.takenNames = Set.copyOf(takenNames);
    }

    /** A fresh world and root hash space per {@code <world>} element (gravity 0: ode4j's default). */
    public static LoadTarget newWorlds() {
        return new LoadTarget(null, null, Pose.identity(), Set.of());
    }

    /** Every {@code <world>} of the document maps onto {@code world}; its spaces go under {@code rootSpace}. */
    public static LoadTarget into(DWorld world, DSpace rootSpace) {
        return new LoadTarget(Objects.requireNonNull(world), Objects.requireNonNull(rootSpace), Pose.identity(), Set.of());
    }

    /**
     * This target with the document's root placed at {@code placement}: every frame, absolute ones
     * included, is measured from it, so one robot file can be put anywhere (an initial pose).
     */
    public LoadTarget placedAt(Pose newPlacement) {
        return new LoadTarget(world, space, newPlacement, takenNames);
    }

    /**
     * This target with names that objects of the target world already carry: a document reusing
     * one (after prefixing) is an error, reported before anything is created.
     */
    public LoadTarget excludingNames(Set<String> names) {
        return new LoadTarget(world, space, placement, names);
    }

    Set<String> takenNames() {
        return takenNames;
    }

    Pose placement() {
        return placement;
    }

    DWorld worldFor() {
        return world != null ? world : OdeHelper.createWorld();
    }

    DSpace rootSpaceFor() {
        return space != null ? space : OdeHelper.createHashSpace(null);
    }

    boolean createsWorlds() {
        return world == null;
    }
}
