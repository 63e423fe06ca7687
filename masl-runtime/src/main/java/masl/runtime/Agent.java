package masl.runtime;

import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
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
 * reschedules the agent when it returns. A program that has finished leaves the agent
 * {@code DONE}.
 *
 * <p><b>Serving while blocked</b> (MASL §5). An invocation queued for a {@code PARKED} or
 * {@code DONE} agent turns it {@code SERVING} and schedules a slice that runs the pending
 * invocations on its behalf, without running its program, then returns it to where it was. An
 * unpark that comes meanwhile turns {@code SERVING → SERVING_WOKEN}, and the serving slice then
 * schedules the program. So an agent is never run by two threads at once, its program and the
 * invocations it serves never overlap, and no wake-up or invocation is lost.
 */
final class Agent implements AgentContext, AgentTask {

    private static final int SCHEDULED = 0;
    private static final int RUNNING = 1;
    private static final int RUNNING_WOKEN = 2;
    private static final int PARKED = 3;
    private static final int SERVING = 4;
    private static final int SERVING_WOKEN = 5;
    private static final int DONE = 6;

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
    public void runSlice() {
        int current = state.get();
        if (current == SERVING || current == SERVING_WOKEN) {
            serveWhileBlocked();
            return;
        }
        if (!state.compareAndSet(SCHEDULED, RUNNING)) {
            // A runtime bug, not the program's: fail the mission rather than the scheduler's thread.
            mission.agentFailed(this, new IllegalStateException(describe() + " scheduled in state " + current));
            return;
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
            serveIfPending();
        } else if (!suspended) {
            end();
            mission.agentFailed(this, new IllegalStateException(describe()
                    + ": resume returned without a suspension or finish()"));
        } else if (state.compareAndSet(RUNNING, PARKED)) {
            // Invocations queued while the slice ran are served now that the agent is blocked.
            serveIfPending();
        } else {
            mission.countSchedule();
            state.set(SCHEDULED);
            mission.scheduler().schedule(this);
        }
    }

    /** The slice of a blocked (or finished) agent: serve its pending invocations, nothing else. */
    private void serveWhileBlocked() {
        try {
            serveInvocations();
        } catch (Throwable failure) {
            end();
            mission.agentFailed(this, failure);
            return;
        }
        if (finished) {
            state.set(DONE);
        } else if (!state.compareAndSet(SERVING, PARKED)) {
            mission.countSchedule();
            state.set(SCHEDULED);
            mission.scheduler().schedule(this);
            return;
        }
        // An invocation queued after the queue was drained found the agent SERVING: serve it too.
        serveIfPending();
    }

    /** Schedules a serving slice if invocations wait and the agent is blocked or done. */
    private void serveIfPending() {
        while (!invocations.isEmpty()) {
            int current = state.get();
            if (current == PARKED) {
                mission.countSchedule();
            } else if (current != DONE) {
                return;
            }
            if (state.compareAndSet(current, SERVING)) {
                mission.scheduler().schedule(this);
                return;
            }
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
            if (current == SERVING && state.compareAndSet(SERVING, SERVING_WOKEN)) {
                return;
            }
            if (current == DONE) {
                return;
            }
            if (current == SCHEDULED || current == RUNNING_WOKEN || current == SERVING_WOKEN) {
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
        mission.outsideWakeUpStarted();
        mission.scheduler().scheduleAfter(ms, () -> {
            unpark(ticket);
            mission.outsideWakeUpEnded();
        });
        return false;
    }

    @Override
    public boolean await(CompletionStage<?> result) {
        CompletableFuture<?> future = result.toCompletableFuture();
        if (future.isDone()) {
            return yieldIfSliceUsed();
        }
        long ticket = prepareToPark();
        mission.outsideWakeUpStarted();
        future.whenComplete((value, failure) -> {
            unpark(ticket);
            mission.outsideWakeUpEnded();
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
     * invocations issue builds on. A running agent runs it at its next step boundary or loop
     * iteration; a blocked or finished one has it run on its behalf at once (§5). An invocation
     * runs the callee's primitive only: served on behalf of a parked agent, it must not use the
     * agent's {@link AgentContext}, whose memberships other agents may be changing meanwhile.
     */
    void submitInvocation(Runnable invocation) {
        invocations.add(invocation);
        serveIfPending();
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
