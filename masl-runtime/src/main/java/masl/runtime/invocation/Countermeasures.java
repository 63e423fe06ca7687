package masl.runtime.invocation;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import masl.runtime.Agent;
import masl.runtime.EntryDefinition;
import masl.runtime.entry.Membership;

/**
 * The countermeasures armed by one agent's launches (MASL §9), in arming order. Confined to the
 * agent's slices.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Countermeasures {

    private final List<Countermeasure> armed = new ArrayList<>();

    public void arm(Countermeasure countermeasure) {
        armed.add(countermeasure);
    }

    /** Invoking a countermeasure explicitly disarms it (§9): every armed one of that primitive of {@code target}. */
    public void disarm(Agent target, String primitive) {
        if (!armed.isEmpty()) {
            armed.removeIf(countermeasure -> countermeasure.target() == target
                    && countermeasure.name().equals(primitive));
        }
    }

    /**
     * The agent is about to leave its blocks ({@code memberships}, outermost first) from the
     * innermost to depth {@code outermostLeft} (0 is its outermost block): disarms the
     * countermeasures armed for them and gives each to {@code fire}, innermost block first, the
     * latest armed first within a block (§9).
     */
    public void fireFor(List<Membership> memberships, int outermostLeft, Consumer<Countermeasure> fire) {
        for (int depth = memberships.size() - 1; depth >= outermostLeft && !armed.isEmpty(); depth--) {
            EntryDefinition block = memberships.get(depth).entry.definition();
            for (int i = armed.size() - 1; i >= 0; i--) {
                Countermeasure countermeasure = armed.get(i);
                if (countermeasure.block() == block) {
                    armed.remove(i);
                    fire.accept(countermeasure);
                }
            }
        }
    }
}
