package masl.sim.xode;

import java.util.Objects;
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

    private LoadTarget(DWorld world, DSpace space) {
        this.world = world;
        this.space = space;
    }

    /** A fresh world and root hash space per {@code <world>} element (gravity 0: ode4j's default). */
    public static LoadTarget newWorlds() {
        return new LoadTarget(null, null);
    }

    /** Every {@code <world>} of the document maps onto {@code world}; its spaces go under {@code rootSpace}. */
    public static LoadTarget into(DWorld world, DSpace rootSpace) {
        return new LoadTarget(Objects.requireNonNull(world), Objects.requireNonNull(rootSpace));
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
