package masl.runtime.entry;

import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import masl.runtime.Agent;
import masl.runtime.ESequence;
import masl.runtime.SharedDeclaration;
import masl.runtime.SharedVariable;

/**
 * The members that run a block between two moments when it is empty (MASL §6.5), and what lives
 * exactly as long as they do: the block's shared variables, which scalar children already ran,
 * and which agents reached each e-sequence of the body (for the free entry barrier, §6.3).
 *
 * <p>All fields but the shared variables are guarded by the {@link EntryCoordinator}'s lock.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Wave {

    /** The block, or {@code null} for the mission's own wave: every agent, parent of {@code main}. */
    final Entry entry;
    final int number;
    /** Members in arrival order: active ones, waiting-out ones, those held inside children. */
    final Set<Agent> members = new LinkedHashSet<>();
    /**
     * Members held by no entry or exit barrier anywhere in their chain of blocks: the members a
     * free entry barrier waits for (§6.3; an exit barrier waits for every member not waiting-out
     * at it, held in a descendant or not). (The query {@code getActiveCount()}
     * counts more, see {@link Entry#getActiveCount}.) Changed only through {@link #activate} and
     * {@link #deactivate}, which keep the reached counts in step.
     */
    int active;
    /** Members held by the exit barrier, in arrival order (synchronous blocks only). */
    final HeldInOrder<Agent> waitingOut = new HeldInOrder<>();
    private final Set<Entry> scalarChildrenRun = new HashSet<>();
    private final Map<ESequence, Reached> reached = new HashMap<>();
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

    /** An agent, active in this wave, counts in it from now on (§6.4). */
    void activate(Agent agent) {
        active++;
        for (Reached sequence : reached.values()) {
            if (sequence.agents.contains(agent)) {
                sequence.active++;
            }
        }
    }

    /** An agent stops counting as active in this wave: held, or no longer a member. */
    void deactivate(Agent agent) {
        active--;
        for (Reached sequence : reached.values()) {
            if (sequence.agents.contains(agent)) {
                sequence.active--;
            }
        }
    }

    /** Records that {@code agent}, active in this wave, reached {@code sequence} during it (§6.3). */
    void markReached(ESequence sequence, Agent agent) {
        if (reached.computeIfAbsent(sequence, s -> new Reached()).agents.add(agent)) {
            reached.get(sequence).active++;
        }
    }

    /** Whether every active member has reached {@code sequence} during this wave; O(1). */
    boolean reachedByAllActive(ESequence sequence) {
        Reached agents = reached.get(sequence);
        return (agents == null ? 0 : agents.active) == active;
    }

    /** The agents that reached one e-sequence during this wave, and how many of them are active in it. */
    private static final class Reached {
        final Set<Agent> agents = new HashSet<>();
        int active;
    }

    @SuppressWarnings("unchecked")
    public <T> SharedVariable<T> shared(SharedDeclaration<T> declaration) {
        return (SharedVariable<T>) shared[declaration.index()];
    }

    @Override
    public String toString() {
        return (entry == null ? "mission" : entry.name()) + " wave " + number;
    }
}
