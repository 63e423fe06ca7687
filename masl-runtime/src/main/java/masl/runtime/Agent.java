package masl.runtime;

import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import masl.runtime.trace.LeaveCause;

/**
 * A MASL agent at run time: an active object with its own program counter (in its
 * {@link AgentProgram}), memberships, event and invocation queues, run slice by slice by the
 * mission's {@link Scheduler}. It is the {@link AgentContext} its program calls.
 *
 * <p><b>Scheduling state machine.</b> {@code SCHEDULED → RUNNING} when a slice starts. A runtime
 * call that must wait issues a park <em>ticket</em> ({@link #prepareToPark()}) and the program
 * returns; the slice then ends {@code RUNNING → PARKED}. Whoever ends the wait calls
 * {@link #unpark(long)} with that ticket: the first unpark of the current ticket wins, a stale or
 * repeated one is ignored. {@code PARKED → SCHEDULED} hands the agent to the scheduler; an unpark
 * that comes while the slice is still running turns {@code RUNNING → RUNNING_WOKEN}, and the slice
 * reschedules the agent when it returns. So an agent is never run by two threads at once and no
 * wake-up is lost.
 */
final class Agent implements AgentContext, AgentTask {

    private static final int SCHEDULED = 0;
    private static final int RUNNING = 1;
    private static final int RUNNING_WOKEN = 2;
    private static final int PARKED = 3;
    private static final int DONE = 4;

    private final int id;
    private final String name;
    final AgentImplementation implementation;
    private final AgentProgram program;
    private final Mission mission;
    private final AtomicInteger state = new AtomicInteger(SCHEDULED);
    /** The ticket of the pending park, 0 if none. */
    private final AtomicLong wakeTicket = new AtomicLong();
    private final Queue<EventOccurrence> events = new ConcurrentLinkedQueue<>();
    private final Queue<Runnable> invocations = new ConcurrentLinkedQueue<>();
    private volatile boolean finished;

    // Confined to the thread running the current slice (successive slices are ordered).
    private long lastTicket;
    private boolean suspended;
    private int stepsThisSlice;
    /** Step boundaries and plain loop iterations passed: "ran an instruction" for busy-waits. */
    private long progress;
    private long busyWaitEpoch = -1;
    private long busyWaitProgress = -1;

    // Guarded by the EntryCoordinator's lock (see its invariant for the agent's own reads).
    final List<Membership> memberships = new ArrayList<>();
    List<Wave> activeIn = new ArrayList<>();
    List<SynchronisationBarrier> participatesIn = new ArrayList<>();
    /** The synchronous block the agent left last, until its next step boundary or arrival. */
    EntryDefinition lastLeftSynchronous;

    Agent(int id, String name, AgentImplementation implementation, AgentProgram program, Mission mission) {
        this.id = id;
        this.name = name;
        this.implementation = implementation;
        this.program = program;
        this.mission = mission;
    }

    // ---- AgentTask -----------------------------------------------------------------------------

    @Override
    public int id() {
        return id;
    }

    @Override
    public boolean finished() {
        return finished;
    }

    @Override
    public void runSlice() {
        if (!state.compareAndSet(SCHEDULED, RUNNING)) {
            throw new IllegalStateException(describe() + " scheduled twice");
        }
        suspended = false;
        stepsThisSlice = 0;
        try {
            program.resume(this);
        } catch (Throwable failure) {
            end();
            mission.agentFailed(this, failure);
            return;
        }
        if (finished) {
            end();
            mission.agentFinished(this);
        } else if (!suspended) {
            end();
            mission.agentFailed(this, new IllegalStateException(describe()
                    + ": resume returned without a suspension or finish()"));
        } else if (!state.compareAndSet(RUNNING, PARKED)) {
            mission.countSchedule();
            state.set(SCHEDULED);
            mission.scheduler().schedule(this);
        }
    }

    /** Parked (waiting for someone else) or done: it cannot make progress on its own. */
    boolean isIdle() {
        int current = state.get();
        return current == PARKED || current == DONE;
    }

    private void end() {
        finished = true;
        state.set(DONE);
    }

    /** Issues the ticket of a park: the caller (this agent's own slice) then returns {@code false}. */
    long prepareToPark() {
        if (suspended) {
            throw new IllegalStateException(describe() + ": runtime called again after a suspension");
        }
        suspended = true;
        long ticket = ++lastTicket;
        wakeTicket.set(ticket);
        return ticket;
    }

    /** The ticket of the pending park, or 0 if the agent has none (it is running, not waiting). */
    long pendingTicket() {
        return wakeTicket.get();
    }

    /** Ends the park that issued {@code ticket}; ignored if that park already ended. */
    void unpark(long ticket) {
        if (ticket == 0 || !wakeTicket.compareAndSet(ticket, 0)) {
            return;
        }
        while (true) {
            int current = state.get();
            if (current == PARKED) {
                // Counted before the agent leaves PARKED, for the deadlock watchdog (Mission).
                mission.countSchedule();
                if (state.compareAndSet(PARKED, SCHEDULED)) {
                    mission.scheduler().schedule(this);
                    return;
                }
                continue;
            }
            if (current == RUNNING && state.compareAndSet(RUNNING, RUNNING_WOKEN)) {
                return;
            }
            if (current == DONE) {
                return;
            }
            if (current == SCHEDULED || current == RUNNING_WOKEN) {
                throw new IllegalStateException(describe() + " woken twice");
            }
        }
    }

    // ---- AgentContext --------------------------------------------------------------------------

    @Override
    public int proxyId() {
        return id;
    }

    @Override
    public boolean stepBoundary() {
        progress++;
        serveInvocations();
        boolean synchronous = isInnermostSynchronous();
        lastLeftSynchronous = null;
        if (synchronous && !mission.coordinator().arriveAtBarrier(this)) {
            return false;
        }
        return yieldIfSliceUsed();
    }

    @Override
    public boolean endOfSequence(ESequence sequence) {
        EntryDefinition innermost = memberships.isEmpty() ? null : innermost().entry.definition();
        if (innermost != sequence.parent()) {
            throw new IllegalStateException(describe() + " ends " + sequence + " inside " + innermost);
        }
        progress++;
        serveInvocations();
        boolean ranSynchronousBlock = lastLeftSynchronous != null && lastLeftSynchronous.sequence() == sequence;
        boolean synchronous = isInnermostSynchronous();
        lastLeftSynchronous = null;
        if (synchronous && !ranSynchronousBlock && !mission.coordinator().arriveAtBarrier(this)) {
            return false;
        }
        return yieldIfSliceUsed();
    }

    @Override
    public boolean loopIteration() {
        progress++;
        serveInvocations();
        return yieldIfSliceUsed();
    }

    @Override
    public boolean busyWaitIteration() {
        serveInvocations();
        long epoch = mission.changes().current();
        if (epoch == busyWaitEpoch && progress == busyWaitProgress) {
            mission.changes().parkUntilChanged(this, epoch);
            return false;
        }
        busyWaitEpoch = epoch;
        busyWaitProgress = progress;
        return yieldIfSliceUsed();
    }

    @Override
    public Arrival enter(EntryDefinition block, boolean test) {
        return mission.coordinator().enter(this, mission.entry(block), test);
    }

    @Override
    public boolean leave(EntryDefinition block) {
        return mission.coordinator().leaveAtEnd(this, mission.entry(block));
    }

    @Override
    public void breakOut(EntryDefinition outermost) {
        mission.coordinator().leaveUpTo(this, mission.entry(outermost), LeaveCause.BREAK);
    }

    @Override
    public void reelect(EntryDefinition block) {
        mission.coordinator().leaveUpTo(this, mission.entry(block), LeaveCause.REELECT);
    }

    @Override
    public void restart(EntryDefinition block) {
        mission.coordinator().leaveUpTo(this, mission.entry(block), LeaveCause.RESTART);
    }

    @Override
    public <T> SharedVariable<T> shared(SharedDeclaration<T> declaration) {
        for (int i = memberships.size() - 1; i >= 0; i--) {
            Membership membership = memberships.get(i);
            if (membership.entry.definition() == declaration.block()) {
                return membership.wave.shared(declaration);
            }
        }
        throw new IllegalStateException(describe() + " reads " + declaration + " outside its block");
    }

    @Override
    public Entry entry(EntryDefinition block) {
        return mission.entry(block);
    }

    @Override
    public boolean sleep(long ms) {
        progress++;
        if (ms <= 0) {
            return yieldIfSliceUsed();
        }
        long ticket = prepareToPark();
        mission.timedWakeUpStarted();
        mission.scheduler().scheduleAfter(ms, () -> {
            unpark(ticket);
            mission.timedWakeUpEnded();
        });
        return false;
    }

    @Override
    public Queue<EventOccurrence> events() {
        return events;
    }

    @Override
    public void finish() {
        if (!memberships.isEmpty()) {
            throw new IllegalStateException(describe() + " finishes inside " + memberships);
        }
        finished = true;
    }

    // ---- runtime side --------------------------------------------------------------------------

    /**
     * Queues an external invocation of one of this agent's primitives (MASL §9): the hook the
     * invocations issue builds on. It runs at the agent's next step boundary or loop iteration.
     */
    void submitInvocation(Runnable invocation) {
        invocations.add(invocation);
        mission.changes().advance();
    }

    private void serveInvocations() {
        Runnable invocation;
        while ((invocation = invocations.poll()) != null) {
            invocation.run();
        }
    }

    private boolean yieldIfSliceUsed() {
        if (++stepsThisSlice < mission.scheduler().stepsPerSlice()) {
            return true;
        }
        unpark(prepareToPark());
        return false;
    }

    private boolean isInnermostSynchronous() {
        return !memberships.isEmpty() && innermost().entry.mode() == Mode.SYNCHRONOUS;
    }

    Membership innermost() {
        return memberships.get(memberships.size() - 1);
    }

    /** Held by an entry or exit barrier: then it is active nowhere (§6.3). */
    boolean isHeld() {
        return !memberships.isEmpty() && innermost().status != Membership.Status.ACTIVE;
    }

    String describe() {
        return "agent " + name + " (" + id + ") at pc " + program.pc();
    }

    @Override
    public String toString() {
        return name;
    }
}
