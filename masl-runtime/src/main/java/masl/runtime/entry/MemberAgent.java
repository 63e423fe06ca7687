package masl.runtime.entry;

import java.util.ArrayList;
import java.util.List;
import masl.runtime.Agent;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.Mode;
import masl.runtime.SharedDeclaration;
import masl.runtime.SharedVariable;
import masl.runtime.scheduling.ScheduledAgent;

/**
 * The block side of an agent ({@code masl.runtime.Agent}): the chain of blocks it is a member of,
 * the waves it is active in, the synchronisation barriers it takes part in and its latest arrival
 * at one. The {@link EntryCoordinator} changes them; the agent reads them. A layer of the agent,
 * not an object of its own, for the reason {@link ScheduledAgent} gives: a lock-step agent-step
 * reads {@link #barrierDue} and writes its arrival.
 *
 * <p><b>Memory consistency effects.</b> The memberships, waves and barriers are guarded by the
 * coordinator's lock. Other agents change them only while this agent is parked (held by an entry
 * or exit barrier), and the wake-up that follows makes the change happen-before its next slice: the
 * agent reads its own memberships without the lock while it runs (the coordinator's invariant).
 * The fields of its latest arrival are written without the lock by its own slice, or by the worker
 * that publishes an arrival it held ({@link ArrivalCombiner}), before the arrival's atomic push,
 * and read under the lock by the barrier it arrived at ({@link SynchronisationBarrier}).
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public abstract class MemberAgent extends ScheduledAgent {

    // Guarded by the EntryCoordinator's lock (see its invariant for the agent's own reads).
    public final List<Membership> memberships = new ArrayList<>();
    public List<Wave> activeIn = new ArrayList<>();
    public List<SynchronisationBarrier> participatesIn = new ArrayList<>();
    /** Its program died: it counts in no wave, not even the mission's (see {@link EntryCoordinator#leaveAll}). */
    public boolean departed;
    /**
     * The barrier its step boundaries arrive at: that of its innermost block if the block is
     * synchronous and the agent active in it, else null. Kept with the memberships, so that a step
     * in lock-step reads this field, not the chain of blocks (a list, its array and a membership,
     * three more cache lines per agent-step).
     */
    public SynchronisationBarrier barrierDue;

    // The agent's latest arrival at a synchronisation barrier (see SynchronisationBarrier): written
    // without the lock by its own slice, or, for an arrival its worker held (ArrivalCombiner), by
    // that worker when it publishes it; read under the lock by the barrier it arrived at.
    /**
     * For an arrival by itself, the agent that arrived before it at the same barrier, while it waits
     * on the barrier's stack; a published chunk holds its agents in an array of its own.
     */
    public Agent nextArrival;
    /** The barrier it arrived at last, until it stops taking part in it; null if none. */
    public SynchronisationBarrier arrivedAt;
    /** The phase of {@link #arrivedAt} its arrival counted in. */
    public int arrivalPhase;
    /**
     * The run that held its latest arrival, or null: the next arrival, mostly made on the same
     * worker, finds the run here instead of asking the scheduler for the calling thread's. Confined
     * to its slices; a stale one (another thread's) is only looked past.
     */
    ArrivalCombiner heldBy;

    protected MemberAgent(int id, String name, AgentProgram program, Mission mission) {
        super(id, name, program, mission);
    }

    public final Membership innermost() {
        return memberships.get(memberships.size() - 1);
    }

    /** Held by an entry or exit barrier: then it is active nowhere (§6.3). */
    public final boolean isHeld() {
        return !memberships.isEmpty() && innermost().status != Membership.Status.ACTIVE;
    }

    /** {@link #barrierDue}; an agent held by a barrier of its innermost block is parked, not running. */
    protected final SynchronisationBarrier barrierDue() {
        SynchronisationBarrier barrier = barrierDue;
        if (barrier == null && isHeld() && innermost().entry.mode() == Mode.SYNCHRONOUS) {
            throw new IllegalStateException(describe() + " runs while " + innermost());
        }
        return barrier;
    }

    /** The agent's innermost block must be {@code parent} ({@code null}: no block) when it ends {@code what} in it. */
    protected final void requireAtLevelOf(EntryDefinition parent, Object what) {
        EntryDefinition innermost = memberships.isEmpty() ? null : innermost().entry.definition();
        if (innermost != parent) {
            throw new IllegalStateException(describe() + " ends " + what + " inside " + innermost);
        }
    }

    /** The depth of {@code block} in the agent's chain of blocks (0: outermost), for leaving up to it. */
    protected final int depthOf(EntryDefinition block) {
        for (int depth = memberships.size() - 1; depth >= 0; depth--) {
            if (memberships.get(depth).entry.definition() == block) {
                return depth;
            }
        }
        // Not a member: the coordinator reports the translator bug.
        return memberships.size();
    }

    /** The blocks of the agent, innermost first: where an occurrence looks for its reaction (§8). */
    protected final List<EntryDefinition> chainInnermostFirst() {
        List<EntryDefinition> chain = new ArrayList<>(memberships.size());
        for (int i = memberships.size() - 1; i >= 0; i--) {
            chain.add(memberships.get(i).entry.definition());
        }
        return chain;
    }

    /** The variable {@code declaration} names in the wave of its block the agent is in (AgentContext). */
    public final <T> SharedVariable<T> shared(SharedDeclaration<T> declaration) {
        for (int i = memberships.size() - 1; i >= 0; i--) {
            Membership membership = memberships.get(i);
            if (membership.entry.definition() == declaration.block()) {
                return membership.wave.shared(declaration);
            }
        }
        throw new IllegalStateException(describe() + " reads " + declaration + " outside its block");
    }
}
