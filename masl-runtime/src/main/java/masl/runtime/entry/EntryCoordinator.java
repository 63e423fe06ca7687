package masl.runtime.entry;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.LongSupplier;
import java.util.function.Supplier;
import masl.runtime.Agent;
import masl.runtime.Arrival;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.Mode;
import masl.runtime.SharedVariable;
import masl.runtime.scheduling.ChangeEpoch;
import masl.runtime.scheduling.SliceRun;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * Owns every membership of a mission: entries, waves, entry/exit barriers and synchronisation
 * barriers (MASL §6). One lock guards them all. The rules cross blocks (a member of a child is a
 * member of every ancestor, a free entry barrier looks at the parent's members, the last member
 * finishing ends a wave while releasing others), and one lock makes each change, with all
 * its consequences, a single atomic step, which is exactly what §6.5 demands of a wave's end. The
 * hot paths that need no membership (shared variables, the journal, events) never take it, nor
 * does an arrival at a synchronisation barrier that does not complete it (the hot path of
 * lock-step: an atomic count and a lock-free stack per barrier, see {@link SynchronisationBarrier});
 * only the trip takes it. Critical sections are short and never run program code.
 *
 * <p><b>Operation shape.</b> Every public operation locks, applies its change, then
 * {@linkplain #settle() settles} the consequences to a fixed point (exit barriers released, waves
 * ended, free entry barriers opened, then synchronisation barriers tripped), and finally, after
 * unlocking, wakes the parked agents it made runnable and advances the change epoch. The trace
 * records under the lock, so it lists changes in the order they happened.
 *
 * <p><b>Invariant.</b> An agent's memberships are changed by other agents only while it is parked
 * (held by an entry or exit barrier); the wake-up that follows publishes the change to it. So an
 * agent may read its own memberships without the lock while it runs.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class EntryCoordinator {

    private final ReentrantLock lock = new ReentrantLock();
    private final Trace trace;
    /** The scheduler's clock: virtual under a seeded scheduler, so a seed reproduces timestamps. */
    private final LongSupplier clock;
    private final ChangeEpoch changes;
    /** The parent wave of {@code main}: every agent of the mission, active unless held. */
    private final Wave missionWave = new Wave(null, 1, new SharedVariable<?>[0]);
    private final Set<Entry> awaitingFirstRelease = new LinkedHashSet<>();
    // Work lists of the operation in progress, used only while holding the lock.
    /** Waves a member left or went waiting-out in: their exit barrier may release (§6.3). */
    private final ArrayDeque<Wave> exitCandidates = new ArrayDeque<>();
    private final Set<SynchronisationBarrier> weakenedBarriers = new LinkedHashSet<>();
    private WakeBatch wakes = new WakeBatch();
    /** A batch woken by an earlier operation, for the next one to reuse; taken under the lock, returned after. */
    private final AtomicReference<WakeBatch> spareWakes = new AtomicReference<>();
    private final Mission mission;
    private boolean changed;
    /** {@link #wake}, made once: a trip hands it its agents without allocating. */
    private final Consumer<Agent> wakeParked = this::wake;
    /** {@link #wakeLater}, made once. */
    private final Consumer<ArrivalChunk> wakeChunkLater = this::wakeLater;
    /** Makes the {@link ArrivalCombiner} of a scheduler thread's run of slices, on its first arrival. */
    private final Function<SliceRun, ArrivalCombiner> newCombiner;

    public EntryCoordinator(Mission mission, Trace trace, LongSupplier clock, ChangeEpoch changes) {
        this.mission = mission;
        this.trace = trace;
        this.clock = clock;
        this.changes = changes;
        this.newCombiner = run -> new ArrivalCombiner(this, mission, run);
    }

    /** Makes the mission's agents members of the mission wave; called once, before they run. */
    public void addAgents(List<Agent> agents) {
        begin();
        try {
            for (Agent agent : agents) {
                missionWave.members.add(agent);
                reconcile(agent);
            }
        } finally {
            end();
        }
    }

    // ---- operations of the running agent ------------------------------------------------------

    public Arrival enter(Agent agent, Entry entry, boolean test) {
        begin();
        try {
            Wave parentWave = parentWaveOf(agent, entry);
            ESequence sequence = entry.definition().sequence();
            // §6.3: reached = entered one of its blocks, or tested and skipped them all
            if (test || sequence.endsWith(entry.definition())) {
                parentWave.markReached(sequence, agent);
            }
            Arrival arrival;
            if (!test || entry.isTopLevelAfterItsWave()) {
                arrival = Arrival.SKIPPED;
            } else if (entry.mode() == Mode.SYNCHRONOUS) {
                holdAtEntry(agent, entry);
                arrival = Arrival.WAITING;
            } else if (entry.mode() == Mode.SCALAR && !parentWave.electScalar(entry)) {
                arrival = Arrival.SKIPPED;
            } else if (entry.isTopLevelBeforeItsWave()) {
                holdAtEntry(agent, entry);
                arrival = Arrival.WAITING;
            } else {
                join(agent, entry);
                arrival = Arrival.ENTERED;
            }
            settle();
            if (arrival == Arrival.WAITING) {
                if (agent.innermost().status == Membership.Status.ACTIVE) {
                    return Arrival.ENTERED;
                }
                agent.prepareToPark();
            }
            return arrival;
        } finally {
            end();
        }
    }

    /** Normal end of the innermost block: true if the agent has left it, false if it parked at the exit barrier. */
    public boolean leaveAtEnd(Agent agent, Entry entry) {
        begin();
        try {
            Membership membership = requireInnermost(agent, entry);
            changed = true;
            if (entry.mode() != Mode.SYNCHRONOUS) {
                pop(agent, LeaveCause.END);
                settle();
                return true;
            }
            membership.status = Membership.Status.WAITING_OUT;
            membership.wave.waitingOut.add(agent);
            exitCandidates.add(membership.wave);
            trace.record(new TraceEvent.WaitingOut(clock.getAsLong(), agent.id(), entry.name(), agent.source()));
            reconcile(agent);
            settle();
            if (agent.memberships.contains(membership)) {
                agent.prepareToPark();
                return false;
            }
            return true;
        } finally {
            end();
        }
    }

    /** Leaves every block up to {@code outermost} inclusive (break, reelect), or up to and excluding it (restart). */
    public void leaveUpTo(Agent agent, Entry outermost, LeaveCause cause) {
        begin();
        try {
            if (!agent.memberships.stream().anyMatch(m -> m.entry == outermost)) {
                throw new IllegalStateException("agent " + agent.id() + " is not a member of " + outermost.name());
            }
            requireActive(agent);
            changed = true;
            while (agent.innermost().entry != outermost) {
                pop(agent, cause);
            }
            if (cause != LeaveCause.RESTART) {
                pop(agent, cause);
            }
            settle();
        } finally {
            end();
        }
    }

    /**
     * The agent's program died: it leaves every block it is in, from the innermost, whatever its
     * status there (active, or held by a barrier if it died in a runtime call), with cause
     * {@code FAILED}. Barriers shrink, exit barriers it held back open, as when a member leaves.
     */
    public void leaveAll(Agent agent) {
        begin();
        try {
            changed = true;
            while (!agent.memberships.isEmpty()) {
                Membership innermost = agent.innermost();
                if (innermost.status == Membership.Status.WAITING_IN) {
                    innermost.entry.waitingIn.remove(agent);
                    agent.memberships.remove(agent.memberships.size() - 1);
                    trace.record(new TraceEvent.Left(clock.getAsLong(), agent.id(), innermost.entry.name(),
                            LeaveCause.FAILED, agent.source()));
                    reconcile(agent);
                    innermost.entry.memberLeft(agent);
                } else {
                    innermost.wave.waitingOut.remove(agent);
                    innermost.status = Membership.Status.ACTIVE;
                    pop(agent, LeaveCause.FAILED);
                }
            }
            agent.departed = true;
            reconcile(agent);
            settle();
        } finally {
            end();
        }
    }

    /**
     * The arrival at {@code barrier}, that of the agent's innermost (synchronous) block, in which
     * it is active ({@link Agent#barrierDue}): true if the agent completed it and tripped it now,
     * false if it is parked until the trip. Only the completing arrival takes the lock (see
     * {@link SynchronisationBarrier} for the races this settles); the agent reads its own
     * memberships without it (see the invariant above). On a scheduler that runs slices in runs,
     * the arrival is left to the run ({@link ArrivalCombiner}), and the agent parks even if it is
     * the last: whoever flushes trips.
     */
    public boolean arriveAtBarrier(Agent agent, SynchronisationBarrier barrier) {
        long ticket = agent.prepareToPark();
        ArrivalCombiner combiner = ArrivalCombiner.ofCallingThread(agent, mission.scheduler(), newCombiner);
        if (combiner != null) {
            combiner.arrive(agent, barrier);
            return false;
        }
        int completedPhase = barrier.arrive(agent);
        if (completedPhase < 0) {
            return false;
        }
        begin();
        try {
            if (!tripsCompleted(barrier, completedPhase, agent)) {
                return false;
            }
            agent.cancelPark(ticket);
            return true;
        } finally {
            end();
        }
    }

    /** Trips the phase that arrivals published together completed, unless a membership change came first. */
    void tripCompleted(SynchronisationBarrier barrier, int phase) {
        begin();
        try {
            tripsCompleted(barrier, phase, null);
        } finally {
            end();
        }
    }

    /**
     * Under the lock: trips the phase the arrivals completed, unless a membership change came first:
     * then either it tripped the phase (and woke the arrived agents) or a new participant keeps it
     * open (and they wait for it); false both ways. {@code going}: the completing arrival, which
     * goes on running if it trips (null: every arrived agent is parked).
     */
    private boolean tripsCompleted(SynchronisationBarrier barrier, int phase, Agent going) {
        if (!barrier.completes(phase)) {
            return false;
        }
        trip(barrier, going);
        return true;
    }

    // ---- entry members that change state -----------------------------------------------------

    void lock(Entry entry) {
        if (entry.mode() != Mode.SYNCHRONOUS) {
            return;
        }
        begin();
        try {
            if (entry.policy != LockPolicy.LOCKED) {
                entry.policy = LockPolicy.LOCKED;
                awaitingFirstRelease.remove(entry);
                changed = true;
            }
        } finally {
            end();
        }
    }

    void release(Entry entry, int n) {
        if (entry.mode() != Mode.SYNCHRONOUS || n <= 0) {
            return;
        }
        begin();
        try {
            releaseWaiting(entry, n);
            settle();
        } finally {
            end();
        }
    }

    /** Evaluates {@code reading} atomically with respect to every membership change. */
    public <V> V query(Supplier<V> reading) {
        lock.lock();
        try {
            return reading.get();
        } finally {
            lock.unlock();
        }
    }

    // ---- the changes ---------------------------------------------------------------------------

    private void join(Agent agent, Entry entry) {
        Wave wave = entry.currentWave != null ? entry.currentWave : startWave(entry);
        wave.members.add(agent);
        entry.memberJoined(agent);
        agent.memberships.add(new Membership(entry, wave, Membership.Status.ACTIVE));
        trace.record(new TraceEvent.Entered(clock.getAsLong(), agent.id(), entry.name(), agent.source()));
        reconcile(agent);
        changed = true;
    }

    private void holdAtEntry(Agent agent, Entry entry) {
        agent.memberships.add(new Membership(entry, null, Membership.Status.WAITING_IN));
        entry.waitingIn.add(agent);
        entry.memberJoined(agent);
        trace.record(new TraceEvent.WaitingIn(clock.getAsLong(), agent.id(), entry.name(), agent.source()));
        reconcile(agent);
        if (entry.policy == LockPolicy.FREE || entry.mode() != Mode.SYNCHRONOUS) {
            // a free entry barrier, or the top-level block before its one wave (§4)
            awaitingFirstRelease.add(entry);
        }
        changed = true;
    }

    private void releaseWaiting(Entry entry, int n) {
        if (entry.waitingIn.isEmpty()) {
            return;
        }
        if (entry.mode() == Mode.SYNCHRONOUS) {
            entry.policy = LockPolicy.LOCKED;
        }
        awaitingFirstRelease.remove(entry);
        for (int released = 0; released < n && !entry.waitingIn.isEmpty(); released++) {
            admit(entry.waitingIn.poll(), entry);
        }
        changed = true;
    }

    private void admit(Agent agent, Entry entry) {
        Membership membership = agent.innermost();
        if (membership.entry != entry || membership.status != Membership.Status.WAITING_IN) {
            throw new IllegalStateException("agent " + agent.id() + " is not waiting in " + entry.name());
        }
        Wave wave = entry.currentWave != null ? entry.currentWave : startWave(entry);
        membership.wave = wave;
        membership.status = Membership.Status.ACTIVE;
        wave.members.add(agent);
        trace.record(new TraceEvent.Released(clock.getAsLong(), agent.id(), entry.name(), wave.number,
                agent.source()));
        reconcile(agent);
        wake(agent);
    }

    /** Removes the agent's innermost membership. */
    private void pop(Agent agent, LeaveCause cause) {
        Membership membership = agent.memberships.remove(agent.memberships.size() - 1);
        Wave wave = membership.wave;
        wave.members.remove(agent);
        exitCandidates.add(wave);
        trace.record(new TraceEvent.Left(clock.getAsLong(), agent.id(), membership.entry.name(), cause,
                agent.source()));
        reconcile(agent);
        if (wave.members.isEmpty() && wave.entry.currentWave == wave) {
            wave.entry.currentWave = null;
            trace.record(new TraceEvent.WaveEnded(clock.getAsLong(), wave.entry.name(), wave.number));
        }
        membership.entry.memberLeft(agent);
    }

    private Wave startWave(Entry entry) {
        Wave wave = new Wave(entry, ++entry.wavesStarted, entry.newSharedVariables(changes));
        entry.currentWave = wave;
        trace.record(new TraceEvent.WaveStarted(clock.getAsLong(), entry.name(), wave.number));
        return wave;
    }

    /**
     * Brings the agent's contribution to active counts and barrier participants in line with its
     * memberships: it counts in the waves of all its blocks (and the mission wave) and in the
     * barriers of all its synchronous blocks, unless it is held or its program died, in which case
     * it counts nowhere.
     * Barriers whose participants drop are queued for {@link #settle()}.
     */
    private void reconcile(Agent agent) {
        List<Wave> waves = new ArrayList<>();
        List<SynchronisationBarrier> barriers = new ArrayList<>();
        if (!agent.isHeld() && !agent.departed) {
            waves.add(missionWave);
            for (Membership membership : agent.memberships) {
                waves.add(membership.wave);
                SynchronisationBarrier barrier = membership.entry.barrier;
                if (barrier != null && !barriers.contains(barrier)) {
                    barriers.add(barrier);
                }
            }
        }
        for (Wave wave : agent.activeIn) {
            if (!waves.contains(wave)) {
                wave.deactivate(agent);
            }
        }
        for (Wave wave : waves) {
            if (!agent.activeIn.contains(wave)) {
                wave.activate(agent);
            }
        }
        for (SynchronisationBarrier barrier : agent.participatesIn) {
            if (!barriers.contains(barrier)) {
                barrier.removeParticipant(agent);
                weakenedBarriers.add(barrier);
            }
        }
        for (SynchronisationBarrier barrier : barriers) {
            if (!agent.participatesIn.contains(barrier)) {
                barrier.addParticipant();
            }
        }
        agent.activeIn = waves;
        agent.participatesIn = barriers;
        agent.barrierDue = barrierDue(agent);
    }

    /** The barrier the agent's step boundaries arrive at ({@link Agent#barrierDue}), from its memberships. */
    private static SynchronisationBarrier barrierDue(Agent agent) {
        if (agent.memberships.isEmpty()) {
            return null;
        }
        Membership innermost = agent.innermost();
        return innermost.status == Membership.Status.ACTIVE && innermost.entry.mode() == Mode.SYNCHRONOUS
                ? innermost.entry.barrier : null;
    }

    /**
     * Applies the consequences of the operation's change, to a fixed point, as part of the same
     * atomic step. Every count that can rise rises first: exit barriers whose every member is
     * waiting-out release their agents, and free entry barriers whose condition now holds open.
     * Only then are the synchronisation barriers whose participants dropped checked, so a barrier
     * never trips on a state the step passes through: the leavers of a child stay in lock-step
     * with its parent, and an agent held by a free entry barrier and let in by the same step is
     * waited for. Releasing and opening only add active members and participants, so they never
     * call for a trip; tripping changes no membership, so it comes last.
     */
    private void settle() {
        do {
            Wave wave;
            while ((wave = exitCandidates.poll()) != null) {
                releaseExitIfAllWaitingOut(wave);
            }
        } while (openFirstWave());
        for (SynchronisationBarrier barrier : weakenedBarriers) {
            if (barrier.isComplete()) {
                trip(barrier, null);
            }
        }
        weakenedBarriers.clear();
    }

    /**
     * §6.3/§6.5: once every member of the wave is waiting-out, they leave, as one step. A member
     * held by a descendant's entry or exit barrier is not waiting-out here: it still has an
     * instruction of this block to run (the descendant, and what follows it), so it keeps the
     * others, and the end of a child's wave never releases its parent's exit barrier in the same
     * step: the agents the child lets go are active in the parent, not waiting-out.
     */
    private void releaseExitIfAllWaitingOut(Wave wave) {
        if (wave.entry == null || wave.waitingOut.isEmpty() || wave.waitingOut.size() != wave.members.size()) {
            return;
        }
        List<Agent> leaving = wave.waitingOut.toList();
        wave.waitingOut.clear();
        for (Agent agent : leaving) {
            pop(agent, LeaveCause.END);
            wake(agent);
        }
    }

    /** Lets the agents that arrived go on; {@code going}, the completing arrival, is running (null: a change trips). */
    private void trip(SynchronisationBarrier barrier, Agent going) {
        int agents = barrier.trip(going, wakeParked, wakeChunkLater);
        trace.record(new TraceEvent.BarrierTripped(clock.getAsLong(), barrier.domain.name(), agents));
    }

    /** Opens one free entry barrier whose condition holds (§6.3); false if none does. */
    private boolean openFirstWave() {
        for (Entry entry : awaitingFirstRelease) {
            if (!entry.waitingIn.isEmpty() && sequenceReachedByAll(entry)) {
                releaseWaiting(entry, Integer.MAX_VALUE);
                return true;
            }
        }
        return false;
    }

    /**
     * Whether every active member of the parent's current wave has reached the entry's e-sequence
     * during that wave (members that left are no longer in it; held ones are not active). For
     * {@code main}, the parent wave is the mission's: every agent must have tested it. O(1): the
     * wave counts its active members that reached each e-sequence.
     */
    private boolean sequenceReachedByAll(Entry entry) {
        Wave parentWave = entry.parent == null ? missionWave : entry.parent.currentWave;
        return parentWave != null && parentWave.reachedByAllActive(entry.definition().sequence());
    }

    // ---- helpers -------------------------------------------------------------------------------

    private Wave parentWaveOf(Agent agent, Entry entry) {
        EntryDefinition parent = entry.definition().parent();
        if (parent == null) {
            if (!agent.memberships.isEmpty()) {
                throw new IllegalStateException("agent " + agent.id() + " arrives at main from " + agent.memberships);
            }
            return missionWave;
        }
        Membership innermost = requireActive(agent);
        if (innermost.entry.definition() != parent) {
            throw new IllegalStateException("agent " + agent.id() + " arrives at " + entry.name()
                    + " but its innermost block is " + innermost.entry.name());
        }
        return innermost.wave;
    }

    private static Membership requireActive(Agent agent) {
        if (agent.memberships.isEmpty()) {
            throw new IllegalStateException("agent " + agent.id() + " is in no block");
        }
        Membership innermost = agent.innermost();
        if (innermost.status != Membership.Status.ACTIVE) {
            throw new IllegalStateException("agent " + agent.id() + " runs while " + innermost);
        }
        return innermost;
    }

    private static Membership requireInnermost(Agent agent, Entry entry) {
        Membership innermost = requireActive(agent);
        if (innermost.entry != entry) {
            throw new IllegalStateException("agent " + agent.id() + " leaves " + entry.name()
                    + " but its innermost block is " + innermost.entry.name());
        }
        return innermost;
    }

    /** Queues a wake-up of a parked agent; the running agent (no pending park) needs none. */
    private void wake(Agent agent) {
        wakes.addParked(agent);
    }

    /** Lets a chunk of arrivals go, to be woken by the thread that runs it: a wake-up pending until then. */
    private void wakeLater(ArrivalChunk chunk) {
        mission.outsideWakeUpStarted();
        wakes.addChunk(chunk);
    }

    private void begin() {
        lock.lock();
    }

    private void end() {
        WakeBatch toWake = null;
        if (!wakes.isEmpty()) {
            toWake = wakes;
            WakeBatch spare = spareWakes.getAndSet(null);
            wakes = spare != null ? spare : new WakeBatch();
        }
        boolean advance = changed;
        exitCandidates.clear();
        weakenedBarriers.clear();
        changed = false;
        lock.unlock();
        if (toWake != null) {
            toWake.wakeAll(mission);
            spareWakes.set(toWake);
        }
        if (advance) {
            changes.advance();
        }
    }
}
