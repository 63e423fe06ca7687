package masl.runtime;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The members that run a block between two moments when it is empty (MASL §6.5), and what lives
 * exactly as long as they do: the block's shared variables, which scalar children already ran,
 * and which agents reached each e-sequence of the body (for the free entry barrier, §6.3).
 *
 * <p>All fields but the shared variables are guarded by the {@link EntryCoordinator}'s lock.
 */
final class Wave {

    /** The block, or {@code null} for the mission's own wave: every agent, parent of {@code main}. */
    final Entry entry;
    final int number;
    /** Members in arrival order: active ones, waiting-out ones, those held inside children. */
    final Set<Agent> members = new LinkedHashSet<>();
    /** Members not held by any entry or exit barrier: the active count of §6.4/§6.7. */
    int active;
    /** Members held by the exit barrier, in arrival order (synchronous blocks only). */
    final List<Agent> waitingOut = new ArrayList<>();
    private final Set<Entry> scalarChildrenRun = new HashSet<>();
    private final Map<ESequence, Set<Agent>> reached = new HashMap<>();
    private final SharedVariable<?>[] shared;

    Wave(Entry entry, int number, SharedVariable<?>[] shared) {
        this.entry = entry;
        this.number = number;
        this.shared = shared;
    }

    /** Elects the caller to run a scalar child in this wave: true for the first caller only. */
    boolean electScalar(Entry scalarChild) {
        return scalarChildrenRun.add(scalarChild);
    }

    void markReached(ESequence sequence, Agent agent) {
        reached.computeIfAbsent(sequence, s -> new HashSet<>()).add(agent);
    }

    boolean hasReached(ESequence sequence, Agent agent) {
        Set<Agent> agents = reached.get(sequence);
        return agents != null && agents.contains(agent);
    }

    @SuppressWarnings("unchecked")
    <T> SharedVariable<T> shared(SharedDeclaration<T> declaration) {
        return (SharedVariable<T>) shared[declaration.index()];
    }

    @Override
    public String toString() {
        return (entry == null ? "mission" : entry.name()) + " wave " + number;
    }
}
