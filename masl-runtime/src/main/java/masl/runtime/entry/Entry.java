package masl.runtime.entry;

import java.util.ArrayList;
import java.util.List;
import masl.runtime.Agent;
import masl.runtime.AgentImplementation;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.SharedDeclaration;
import masl.runtime.SharedVariable;
import masl.runtime.scheduling.ChangeEpoch;

/**
 * The state of one e-block in one mission, and its entry members (MASL §6.7).
 *
 * <p>Members are counted as §6.4 says: a member of a child is a member of this block too, and
 * counts as active here unless this block's own entry or exit barrier holds it (one held by a
 * descendant's barrier still has an instruction of this block to run: the descendant). Every member method reads or changes the state atomically with respect to all
 * membership changes of the mission; a value it returns may be stale by the time it is used, as
 * for any concurrent counter.
 *
 * <p>The fields are guarded by the mission's {@link EntryCoordinator} lock. Not final for one subclass
 * only: the entry a deployed agent's program uses in another JVM (the JADE bridge's), each of whose
 * members is a request to the mission's own entry.
 */
public class Entry {

    private final EntryDefinition definition;
    private final EntryCoordinator coordinator;
    final Entry parent;
    /** The barrier of this block's barrier domain; {@code null} unless synchronous. */
    final SynchronisationBarrier barrier;
    Wave currentWave;
    int wavesStarted;
    /** Agents held by the entry barrier, in arrival order (synchronous blocks only). */
    final HeldInOrder<Agent> waitingIn = new HeldInOrder<>();
    LockPolicy policy;
    /** The members (held by the entry barrier, or in the current wave), for shared events (§8). */
    private final Perceivers<Agent> perceivers = new Perceivers<>();

    /** <b>Internal:</b> not part of the API. */
    public Entry(EntryDefinition definition, Entry parent, EntryCoordinator coordinator) {
        this.definition = definition;
        this.parent = parent;
        this.coordinator = coordinator;
        if (definition.mode() == Mode.SYNCHRONOUS) {
            boolean sharesParentDomain = parent != null && parent.mode() == Mode.SYNCHRONOUS;
            barrier = sharesParentDomain ? parent.barrier : new SynchronisationBarrier(this);
            policy = LockPolicy.FREE;
        } else {
            barrier = null;
            policy = LockPolicy.UNAVAILABLE;
        }
    }

    /** The top-level block before its one wave (§4): whatever its mode, it holds arrivals until every agent has tested it. */
    boolean isTopLevelBeforeItsWave() {
        return parent == null && wavesStarted == 0;
    }

    /** The top-level block after its one wave ended (§4): it is never entered again. */
    boolean isTopLevelAfterItsWave() {
        return parent == null && wavesStarted > 0 && currentWave == null;
    }

    public EntryDefinition definition() {
        return definition;
    }

    public String name() {
        return definition.name();
    }

    public Mode mode() {
        return definition.mode();
    }

    /** {@code e.count}: the members, whatever they are doing. */
    public int count() {
        return coordinator.query(() -> waitingIn.size() + (currentWave == null ? 0 : currentWave.members.size()));
    }

    /** {@code e.getList()}: the members' agents, wave members first, each group in arrival order. */
    public List<AgentImplementation> getList() {
        return coordinator.query(() -> {
            List<AgentImplementation> list = implementations(waveMembers(false));
            waitingIn.forEach(agent -> list.add(agent.implementation));
            return list;
        });
    }

    /** {@code e.getActiveCount()}: members held by neither this block's entry barrier nor its exit barrier. */
    public int getActiveCount() {
        return coordinator.query(() -> currentWave == null ? 0 : currentWave.members.size() - currentWave.waitingOut.size());
    }

    public List<AgentImplementation> getActiveList() {
        return coordinator.query(() -> implementations(waveMembers(true)));
    }

    /** {@code e.getWaitingInCount()}: agents held by this block's entry barrier. */
    public int getWaitingInCount() {
        return coordinator.query(waitingIn::size);
    }

    public List<AgentImplementation> getWaitingInList() {
        return coordinator.query(() -> implementations(waitingIn.toList()));
    }

    /** {@code e.getWaitingOutCount()}: agents held by this block's exit barrier. */
    public int getWaitingOutCount() {
        return coordinator.query(() -> currentWave == null ? 0 : currentWave.waitingOut.size());
    }

    public List<AgentImplementation> getWaitingOutList() {
        return coordinator.query(() -> implementations(currentWave == null ? List.of() : currentWave.waitingOut.toList()));
    }

    /** {@code e.getLockPolicy()}: {@code "unavailable"}, {@code "free"} or {@code "locked"}. */
    public String getLockPolicy() {
        return coordinator.query(() -> policy.maslName());
    }

    /** {@code e.lock()}: from now on only {@code release} lets agents in; no effect unless synchronous. */
    public void lock() {
        coordinator.lock(this);
    }

    /** {@code e.release()}: lets every waiting agent in; no effect unless synchronous. */
    public void release() {
        coordinator.release(this, Integer.MAX_VALUE);
    }

    /**
     * {@code e.release(n)}: lets the {@code n} earliest waiting agents in (all of them if fewer
     * wait); no effect unless synchronous. They join the current wave, or start a new one if the
     * block is empty.
     */
    public void release(int n) {
        coordinator.release(this, n);
    }

    /**
     * The members as of the last change: the receivers of a shared event of this block (§8); lock-free.
     * <b>Internal:</b> not part of the API.
     */
    public Agent[] perceivers() {
        return perceivers.snapshot(Agent[]::new);
    }

    /** Records a new member (held by the entry barrier or in the wave); under the coordinator's lock. */
    void memberJoined(Agent agent) {
        perceivers.add(agent);
    }

    /** Records that a member left the block; under the coordinator's lock. */
    void memberLeft(Agent agent) {
        perceivers.remove(agent);
    }

    SharedVariable<?>[] newSharedVariables(ChangeEpoch changes) {
        List<SharedDeclaration<?>> declarations = definition.sharedDeclarations();
        SharedVariable<?>[] variables = new SharedVariable<?>[declarations.size()];
        for (SharedDeclaration<?> declaration : declarations) {
            variables[declaration.index()] = new SharedVariable<>(declaration, changes);
        }
        return variables;
    }

    private List<Agent> waveMembers(boolean activeOnly) {
        List<Agent> members = new ArrayList<>();
        if (currentWave != null) {
            for (Agent member : currentWave.members) {
                if (!activeOnly || !currentWave.waitingOut.contains(member)) {
                    members.add(member);
                }
            }
        }
        return members;
    }

    private static List<AgentImplementation> implementations(List<Agent> agents) {
        List<AgentImplementation> list = new ArrayList<>(agents.size());
        agents.forEach(agent -> list.add(agent.implementation));
        return list;
    }

    @Override
    public String toString() {
        return definition.toString();
    }
}
