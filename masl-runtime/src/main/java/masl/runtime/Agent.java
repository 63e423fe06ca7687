package masl.runtime;

import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Supplier;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.PermeabilityState.Requester;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.entry.Entry;
import masl.runtime.entry.EntryCoordinator;
import masl.runtime.entry.Membership;
import masl.runtime.entry.SynchronisationBarrier;
import masl.runtime.entry.Wave;
import masl.runtime.event.EventOccurrence;
import masl.runtime.event.EventQueue;
import masl.runtime.event.ReactionPlan;
import masl.runtime.event.ReactionRun;
import masl.runtime.invocation.Countermeasure;
import masl.runtime.invocation.PendingInvocation;
import masl.runtime.invocation.Permeability;
import masl.runtime.scheduling.AgentTask;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.TraceEvent;

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
 * invocations it serves never overlap, and no wake-up or invocation is lost. An invocation from
 * outside the mission that its requester lets be served inline
 * ({@link #submitInvocationServingInline}, the JADE bridge's FIPA requests) takes the same
 * {@code SERVING} state but is served at once on the submitting thread, saving the hop to the
 * agent's thread; invocations between the mission's agents ({@link #invoke}) are served by a
 * scheduled slice, so that the order of slices stays the scheduler's (a seeded run replays).
 *
 * <p><b>Events</b> (MASL §8). Emitters push occurrences onto the agent's lock-free
 * {@link EventQueue}, and unpark it if it is parked in a busy-wait (§5). At a step boundary or
 * loop iteration the agent takes the whole queue and plans the reactions ({@link ReactionPlan}).
 * If there are any, it <em>redirects</em> its program: it saves {@code pc} (where the interrupted
 * boundary continues), sets {@code pc} to the first reaction's code, and the boundary call returns
 * {@code false}; the slice then calls {@code resume} again at once. Each reaction ends with
 * {@link #endReaction()}, which redirects to the next one, or lets the last one apply its ending
 * (§8: the last reaction decides): {@link #resumeInterrupted()}, or a break, restart or reelect.
 *
 * <p><b>Invocations and permeability</b> (MASL §9, §11). An external invocation is a
 * {@link PendingInvocation} in the callee's queue; whoever serves it (the callee at a boundary, or
 * a serving slice on its behalf) decides at that moment, from the callee's current state and the
 * requester's relation to it, whether it runs or is denied. While the agent is in
 * {@code wait(state)} it is <em>attentive</em>: a serving slice runs only the first pending
 * invocation that state allows, which ends the wait; the others stay queued.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Agent implements AgentContext, AgentTask {

    private static final int SCHEDULED = 0;
    private static final int RUNNING = 1;
    private static final int RUNNING_WOKEN = 2;
    private static final int PARKED = 3;
    private static final int SERVING = 4;
    private static final int SERVING_WOKEN = 5;
    private static final int DONE = 6;

    private final int id;
    private final String name;
    public final AgentImplementation implementation;
    private final AgentProgram program;
    private final Mission mission;
    private final AtomicInteger state = new AtomicInteger(SCHEDULED);
    /** The ticket of the pending park, 0 if none. */
    private final AtomicLong wakeTicket = new AtomicLong();
    private final EventQueue events = new EventQueue();
    /** The ticket of the agent's latest busy-wait park: an event perceived then wakes it (§5). */
    private volatile long busyWaitTicket;
    /** Whether the agent's latest park is a busy-wait's: for the deadlock watchdog (Mission). */
    private volatile boolean busyWaitPark;
    private final Queue<PendingInvocation> invocations = new ConcurrentLinkedQueue<>();
    private final Permeability permeability;
    /** The ticket of the park of a pending {@code wait(state)}, 0 if none: who zeroes it ends the wait. */
    private final AtomicLong attentiveTicket = new AtomicLong();
    /** The state of the pending {@code wait(state)}; read only while {@link #attentiveTicket} is set. */
    private volatile PermeabilityState attentiveState;
    /** Countermeasures armed by this agent's launches, in arming order; confined to its slices. */
    private final List<Countermeasure> armed = new ArrayList<>();
    private volatile boolean finished;

    // Confined to the thread running the current slice (successive slices are ordered).
    private long lastTicket;
    private boolean suspended;
    private int stepsThisSlice;
    /** Step boundaries and plain loop iterations passed: "ran an instruction" for busy-waits. */
    private long progress;
    private long busyWaitEpoch = -1;
    private long busyWaitProgress = -1;
    /** The program's pc was set to other code: resume it at once, in this slice. */
    private boolean redirected;
    /** The event processing whose reactions are running; null outside reactions. */
    private ReactionRun reacting;
    /** The processing whose last reaction has ended and is applying its ending (resume, break, …). */
    private ReactionRun ending;
    /**
     * The resumption point whose MASL statement the agent is at, for trace records and reports: the
     * case making the current runtime call. A suspending call comes after {@code pc} was set to the
     * case that follows it (the contract numbers cases in program order), a loop iteration or a call
     * in the middle of a case finds {@code pc} at its own case. Read by others only while parked.
     */
    private int statementPc;
    /** Whether {@link #statementPc} is a loop's head, whose statement is the loop, not the last one of its body. */
    private boolean statementIsLoop;
    /** {@link #statementPc} of the boundary whose events are being reacted to. */
    private int interruptedStatementPc;
    private boolean interruptedStatementIsLoop;

    // Guarded by the EntryCoordinator's lock (see its invariant for the agent's own reads).
    public final List<Membership> memberships = new ArrayList<>();
    public List<Wave> activeIn = new ArrayList<>();
    public List<SynchronisationBarrier> participatesIn = new ArrayList<>();
    /** Its program died: it counts in no wave, not even the mission's (see {@link EntryCoordinator#leaveAll}). */
    public boolean departed;

    // The agent's latest arrival at a synchronisation barrier (see SynchronisationBarrier): written
    // by its own slice without the lock, read under the lock by the barrier it arrived at.
    /** The agent that arrived before it at the same barrier, while it waits on the barrier's stack. */
    public Agent nextArrival;
    /** The barrier it arrived at last, until it stops taking part in it; null if none. */
    public SynchronisationBarrier arrivedAt;
    /** The phase of {@link #arrivedAt} its arrival counted in. */
    public int arrivalPhase;

    Agent(int id, String name, AgentImplementation implementation, AgentType type, AgentProgram program,
            Mission mission) {
        this.id = id;
        this.permeability = new Permeability(type);
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
        stepsThisSlice = 0;
        try {
            do {
                suspended = false;
                redirected = false;
                program.resume(this);
            } while (redirected && !finished);
        } catch (Throwable failure) {
            die(failure);
            return;
        }
        if (finished) {
            end();
            mission.agentFinished(this);
            serveIfPending();
        } else if (!suspended) {
            die(new IllegalStateException(describe() + ": resume returned without a suspension or finish()"));
        } else if (!endSliceParked(RUNNING)) {
            mission.countSchedule();
            state.set(SCHEDULED);
            mission.scheduler().schedule(this);
        }
    }

    /**
     * Serves the pending invocations of a blocked (or finished) agent, nothing else, then returns it
     * to where it was: in a serving slice, or on the submitting thread for an invocation served inline.
     */
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
            // An invocation queued after the queue was drained found the agent SERVING: serve it too.
            serveIfPending();
        } else if (!endSliceParked(SERVING)) {
            mission.countSchedule();
            state.set(SCHEDULED);
            mission.scheduler().schedule(this);
        }
    }

    /**
     * Ends the current slice {@code from → PARKED} unless an unpark came meanwhile (false), then
     * serves the invocations queued while the slice ran, now that the agent is blocked. Parked in
     * {@code wait(state)}, the agent is idle for the deadlock watchdog even with invocations queued
     * (its state may allow none of them), so serving one is a wake-up: pending from before the agent
     * turns {@code PARKED} until it is {@code SERVING} (see {@link Mission}, "Deadlock watchdog").
     */
    private boolean endSliceParked(int from) {
        // Only the agent's own program makes it attentive: no wait can begin during this call.
        boolean attentive = attentiveTicket.get() != 0;
        if (attentive) {
            mission.outsideWakeUpStarted();
        }
        try {
            if (!state.compareAndSet(from, PARKED)) {
                return false;
            }
            serveIfPending();
            return true;
        } finally {
            if (attentive) {
                mission.outsideWakeUpEnded();
            }
        }
    }

    /** Schedules a serving slice if invocations wait and the agent is blocked or done. */
    private void serveIfPending() {
        if (claimServing()) {
            mission.scheduler().schedule(this);
        }
    }

    /**
     * Turns a blocked or finished agent {@code SERVING} if invocations wait for it: true if this
     * caller did and must now serve them (or have them served). A parked agent leaving {@code PARKED}
     * counts as a schedule for the deadlock watchdog, as an unpark does; {@code SERVING} is not idle.
     */
    private boolean claimServing() {
        while (hasServable()) {
            int current = state.get();
            if (current == PARKED) {
                mission.countSchedule();
            } else if (current != DONE) {
                return false;
            }
            if (state.compareAndSet(current, SERVING)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Idle, for the deadlock watchdog: it runs nothing until it is woken. Parked (waiting for someone
     * else) or done, with no invocation queued (a queued one is always served soon: by a serving
     * slice, or by the agent at its next boundary); parked in {@code wait(state)}, even with
     * invocations queued, which its state may not allow. The queue is read first: the state read
     * after it then says whether the agent was idle at that instant, as nothing the watchdog waits
     * out queues an invocation uncounted (see {@link Mission}, "Deadlock watchdog").
     */
    boolean isIdle() {
        boolean nothingQueued = invocations.isEmpty();
        int current = state.get();
        if (current == DONE) {
            return nothingQueued;
        }
        return current == PARKED && (nothingQueued || attentiveTicket.get() != 0);
    }

    /** Its program is over (finished or died); the mission may not have counted it out yet. */
    boolean isDone() {
        return state.get() == DONE;
    }

    /** Parked in a busy-wait: waiting for a change, which an outside invocation is. */
    boolean isParkedInBusyWait() {
        return state.get() == PARKED && busyWaitPark;
    }

    private void end() {
        finished = true;
        state.set(DONE);
    }

    /**
     * Something escaped from the program (an {@code Error}, or an exception outside the calls the
     * translator guards): the agent's program is over. It fires its armed countermeasures and leaves
     * every block, so barriers shrink and the others go on; the trace says why ({@code agent-failed})
     * and the mission, once over, fails with this cause.
     */
    private void die(Throwable failure) {
        statementPc = program.pc();
        statementIsLoop = false;
        mission.trace().record(new TraceEvent.AgentFailed(now(), id, String.valueOf(failure), source()));
        try {
            reacting = null;
            ending = null;
            fireCountermeasures(0);
            mission.coordinator().leaveAll(this);
        } catch (RuntimeException leaving) {
            failure.addSuppressed(leaving);
            mission.agentFailed(this, failure);
        }
        end();
        mission.agentDied(this, failure);
        serveIfPending();
    }

    /** Issues the ticket of a park: the caller (this agent's own slice) then returns {@code false}. */
    public long prepareToPark() {
        if (suspended) {
            throw new IllegalStateException(describe() + ": runtime called again after a suspension");
        }
        suspended = true;
        busyWaitPark = false;
        long ticket = ++lastTicket;
        wakeTicket.set(ticket);
        return ticket;
    }

    /**
     * Takes back the park that issued {@code ticket}, which nobody has ended: the call that issued
     * it goes on without waiting after all (the arrival that completes a synchronisation barrier).
     */
    public void cancelPark(long ticket) {
        if (!wakeTicket.compareAndSet(ticket, 0)) {
            throw new IllegalStateException(describe() + ": its park was ended before it was taken back");
        }
        suspended = false;
    }

    /** The ticket of the pending park, or 0 if the agent has none (it is running, not waiting). */
    public long pendingTicket() {
        return wakeTicket.get();
    }

    /** Ends the park that issued {@code ticket}; ignored if that park already ended. */
    public void unpark(long ticket) {
        if (endPark(ticket)) {
            // Counted before the agent leaves PARKED, for the deadlock watchdog (Mission).
            mission.countSchedule();
            if (leavePark()) {
                mission.scheduler().schedule(this);
            }
        }
    }

    /**
     * Claims the end of the park that issued {@code ticket}, as the first half of {@link #unpark}:
     * false if that park already ended. The claimant must then call {@link #leavePark()}.
     */
    public boolean endPark(long ticket) {
        return ticket != 0 && wakeTicket.compareAndSet(ticket, 0);
    }

    /**
     * The second half of an unpark whose {@link #endPark} succeeded, after the watchdog's count:
     * true if the agent went {@code PARKED → SCHEDULED} and the caller must hand it to the
     * scheduler; false if its slice (running or serving) notes the wake-up and reschedules it.
     */
    public boolean leavePark() {
        while (true) {
            int current = state.get();
            if (current == PARKED && state.compareAndSet(PARKED, SCHEDULED)) {
                return true;
            }
            if (current == RUNNING && state.compareAndSet(RUNNING, RUNNING_WOKEN)) {
                return false;
            }
            if (current == SERVING && state.compareAndSet(SERVING, SERVING_WOKEN)) {
                return false;
            }
            if (current == DONE) {
                return false;
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
        atCallBefore();
        requireOutsideReaction("a step boundary");
        progress++;
        boolean synchronous = isInnermostSynchronous();
        if (startReactions(synchronous)) {
            return false;
        }
        return completeBoundary(synchronous);
    }

    /** Steps 2 and 3 of a step boundary (§5): pending invocations, then the barrier if one is due. */
    private boolean completeBoundary(boolean barrier) {
        serveInvocations();
        if (barrier && !mission.coordinator().arriveAtBarrier(this)) {
            return false;
        }
        return yieldIfSliceUsed();
    }

    @Override
    public boolean endOfChild(EntryDefinition block) {
        atCallBefore();
        requireAtLevelOf(block.parent(), block);
        requireOutsideReaction("the end of " + block.name());
        progress++;
        boolean synchronous = isInnermostSynchronous();
        if (startReactions(synchronous)) {
            return false;
        }
        return completeBoundary(synchronous);
    }

    @Override
    public boolean endOfSequence(ESequence sequence) {
        atCallBefore();
        requireAtLevelOf(sequence.parent(), sequence);
        requireOutsideReaction("the end of an e-sequence");
        progress++;
        if (startReactions(false)) {
            return false;
        }
        return completeBoundary(false);
    }

    /** The agent's innermost block must be {@code parent} ({@code null}: no block) when it ends {@code what} in it. */
    private void requireAtLevelOf(EntryDefinition parent, Object what) {
        EntryDefinition innermost = memberships.isEmpty() ? null : innermost().entry.definition();
        if (innermost != parent) {
            throw new IllegalStateException(describe() + " ends " + what + " inside " + innermost);
        }
    }

    @Override
    public boolean loopIteration() {
        atLoopHead();
        progress++;
        if (isReacting()) {
            return yieldIfSliceUsed();
        }
        if (startReactions(false)) {
            return false;
        }
        return completeBoundary(false);
    }

    @Override
    public boolean busyWaitIteration() {
        atLoopHead();
        if (!isReacting()) {
            // Reactions assign locals: running them is progress, so the next iteration does not park.
            if (startReactions(false)) {
                return false;
            }
            serveInvocations();
        }
        long epoch = mission.changes().current();
        if (epoch == busyWaitEpoch && progress == busyWaitProgress) {
            long ticket = mission.changes().parkUntilChanged(this, epoch);
            busyWaitPark = true;
            busyWaitTicket = ticket;
            // An emitter that pushed before the ticket was published has not woken us: wake ourselves.
            if (!isReacting() && !events.isEmpty()) {
                unpark(ticket);
            }
            return false;
        }
        busyWaitEpoch = epoch;
        busyWaitProgress = progress;
        return yieldIfSliceUsed();
    }

    @Override
    public Arrival enter(EntryDefinition block, boolean test) {
        atCallBefore();
        requireOutsideReaction("arriving at " + block);
        return mission.coordinator().enter(this, mission.entry(block), test);
    }

    @Override
    public boolean leave(EntryDefinition block) {
        atCallBefore();
        requireOutsideReaction("leaving " + block);
        fireCountermeasures(memberships.size() - 1);
        return mission.coordinator().leaveAtEnd(this, mission.entry(block));
    }

    @Override
    public void breakOut(EntryDefinition outermost) {
        atCurrentCase();
        requireNoReactionRunning("break");
        ending = null;
        fireCountermeasures(depthOf(outermost));
        mission.coordinator().leaveUpTo(this, mission.entry(outermost), LeaveCause.BREAK);
    }

    @Override
    public void reelect(EntryDefinition block) {
        atCurrentCase();
        requireNoReactionRunning("reelect");
        ending = null;
        fireCountermeasures(depthOf(block));
        mission.coordinator().leaveUpTo(this, mission.entry(block), LeaveCause.REELECT);
    }

    @Override
    public void restart(EntryDefinition block) {
        atCurrentCase();
        requireNoReactionRunning("restart");
        ending = null;
        fireCountermeasures(depthOf(block) + 1);
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
        atCallBefore();
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
        atCallBefore();
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
    public void emit(Event event) {
        emit(event, "");
    }

    @Override
    public void emit(Event event, String message) {
        atCurrentCase();
        if (event.isSystemEvent()) {
            raise(event, message);
            return;
        }
        Entry block = mission.entry(event.block());
        requireMember(event, block);
        Agent[] receivers = event.isShared() ? block.perceivers() : new Agent[] {this};
        EventOccurrence occurrence = new EventOccurrence(event, message, id);
        mission.trace().record(new TraceEvent.EventEmitted(now(), id, event.name(), block.name(), message,
                receivers.length, source()));
        for (Agent receiver : receivers) {
            receiver.perceive(occurrence);
        }
    }

    @Override
    public void uncaughtException(Throwable thrown) {
        atCurrentCase();
        emit(Event.UNCAUGHT_EXCEPTION, RemotePrimitiveException.classNameOf(thrown));
    }

    @Override
    public String messageOf(Event event) {
        if (reacting == null || reacting.current().event() != event) {
            return null;
        }
        return reacting.current().message();
    }

    @Override
    public boolean endReaction() {
        if (reacting == null) {
            throw new IllegalStateException(describe() + ": endReaction outside a reaction");
        }
        if (reacting.hasNext()) {
            redirectToNextReaction();
            return false;
        }
        ending = reacting;
        reacting = null;
        return true;
    }

    @Override
    public boolean resumeInterrupted() {
        if (ending == null) {
            throw new IllegalStateException(describe() + ": resume without a reaction that just ended");
        }
        ReactionRun ended = ending;
        ending = null;
        program.jump(ended.interruptedPc());
        statementPc = interruptedStatementPc;
        statementIsLoop = interruptedStatementIsLoop;
        return completeBoundary(ended.barrierDue());
    }

    @Override
    public void clearEvents() {
        if (reacting == null) {
            throw new IllegalStateException(describe() + ": clearEvents outside a reaction");
        }
        reacting.dropRest().forEach(this::traceDropped);
        events.takeAll().forEach(this::traceDropped);
    }

    @Override
    public void finish() {
        if (!memberships.isEmpty()) {
            throw new IllegalStateException(describe() + " finishes inside " + memberships);
        }
        finished = true;
    }

    @Override
    public <T> CompletableFuture<T> invoke(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call) {
        atCurrentCase();
        if (callee == null) {
            return CompletableFuture.completedFuture(nullAgent(defaultValue));
        }
        Agent target = mission.agentOf(callee);
        disarm(target, primitive);
        if (target == this) {
            return CompletableFuture.completedFuture(invokeSelf(primitive, defaultValue, call));
        }
        CompletableFuture<T> result = new CompletableFuture<>();
        mission.trace().record(new TraceEvent.InvocationMade(now(), id, target.id, primitive, source()));
        target.submitInvocation(new PendingInvocation(this, primitive,
                () -> result.complete(runFor(this, primitive, call, defaultValue)),
                () -> {
                    raise(Event.TIMEOUT, primitive);
                    result.complete(defaultValue);
                }));
        return result;
    }

    @Override
    public <T> T invokeSelf(String primitive, T defaultValue, Callable<T> call) {
        atCurrentCase();
        disarm(this, primitive);
        if (!allowsOwn(primitive)) {
            return defaultValue;
        }
        return runFor(this, primitive, call, defaultValue);
    }

    /**
     * Whether the current state lets this agent invoke its own {@code primitive}; if not, the
     * denial's effects (§11): traced, and {@code timeout} perceived.
     */
    private boolean allowsOwn(String primitive) {
        PermeabilityState state = permeability.current();
        if (Permeability.allows(state, permeability.primitiveId(primitive), Requester.SELF, PermeabilityState.INVOKE)) {
            return true;
        }
        mission.trace().record(new TraceEvent.InvocationDenied(now(), id, id, primitive, state.name(), source()));
        raise(Event.TIMEOUT, primitive);
        return false;
    }

    @Override
    public <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call) {
        return launch(callee, primitive, defaultValue, call, null, null);
    }

    @Override
    public <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call, String countermeasure, Callable<?> countermeasureCall) {
        atCurrentCase();
        if (callee == null) {
            return CompletableFuture.completedFuture(nullAgent(defaultValue));
        }
        Agent target = mission.agentOf(callee);
        disarm(target, primitive);
        CompletableFuture<T> result = start(target, primitive, defaultValue, call);
        if (countermeasure != null && !memberships.isEmpty()) {
            armed.add(new Countermeasure(innermost().entry.definition(), target, countermeasure,
                    countermeasureCall, result, defaultValue));
        }
        return result;
    }

    /** Launches an asynchronous primitive of {@code target}, filtered by permeability, without (dis)arming anything. */
    private <T> CompletableFuture<T> start(Agent target, String primitive, T defaultValue, Callable<T> call) {
        CompletableFuture<T> result = new CompletableFuture<>();
        Runnable start = () -> mission.runAsynchronously(this, () -> result.complete(runFor(this, primitive, call, defaultValue)));
        if (target == this) {
            if (allowsOwn(primitive)) {
                start.run();
            } else {
                result.complete(defaultValue);
            }
        } else {
            mission.trace().record(new TraceEvent.InvocationMade(now(), id, target.id, primitive, source()));
            target.submitInvocation(new PendingInvocation(this, primitive, start, () -> {
                raise(Event.TIMEOUT, primitive);
                result.complete(defaultValue);
            }));
        }
        return result;
    }

    @Override
    public Label newLabel() {
        return new Label(mission.changes());
    }

    /** Invoking a countermeasure explicitly disarms it (§9): every armed one of that primitive of {@code target}. */
    private void disarm(Agent target, String primitive) {
        if (!armed.isEmpty()) {
            armed.removeIf(countermeasure -> countermeasure.target() == target
                    && countermeasure.name().equals(primitive));
        }
    }

    /**
     * The agent is about to leave its blocks from the innermost to depth {@code outermostLeft} (0 is
     * its outermost block): fires the countermeasures armed for them, innermost block first, the
     * latest armed first within a block (§9).
     */
    private void fireCountermeasures(int outermostLeft) {
        for (int depth = memberships.size() - 1; depth >= outermostLeft && !armed.isEmpty(); depth--) {
            EntryDefinition block = memberships.get(depth).entry.definition();
            for (int i = armed.size() - 1; i >= 0; i--) {
                Countermeasure countermeasure = armed.get(i);
                if (countermeasure.block() == block) {
                    armed.remove(i);
                    fire(countermeasure);
                }
            }
        }
    }

    private void fire(Countermeasure countermeasure) {
        mission.trace().record(new TraceEvent.CountermeasureFired(now(), id, countermeasure.target().id,
                countermeasure.name(), countermeasure.block().name(), source()));
        countermeasure.completeLaunch();
        // Not launch(): a fired countermeasure disarms no other armed one (of an outer block).
        start(countermeasure.target(), countermeasure.name(), null, countermeasure.call());
    }

    /** The depth of {@code block} in the agent's chain of blocks (0: outermost), for leaving up to it. */
    private int depthOf(EntryDefinition block) {
        for (int depth = memberships.size() - 1; depth >= 0; depth--) {
            if (memberships.get(depth).entry.definition() == block) {
                return depth;
            }
        }
        // Not a member: the coordinator reports the translator bug.
        return memberships.size();
    }

    /**
     * A member of an agent variable holding {@code null} was used: as for a Java call that throws
     * (§8), the agent perceives {@code uncaught_exception} ({@code java.lang.NullPointerException})
     * and the value is the default.
     */
    private <T> T nullAgent(T defaultValue) {
        uncaughtException(new NullPointerException());
        return defaultValue;
    }

    /**
     * Runs primitive {@code primitive} for {@code requester}: an exception becomes its
     * {@code uncaught_exception} (§9); a refusal by the agent's body, or running past the mission's
     * call timeout, its {@code timeout}.
     */
    private static <T> T runFor(Agent requester, String primitive, Callable<T> call, T defaultValue) {
        try {
            return requester.mission.callPrimitive(call);
        } catch (Mission.PrimitiveTimedOut late) {
            requester.raise(Event.TIMEOUT, primitive);
            return defaultValue;
        } catch (InvocationRefusedException refused) {
            requester.raise(Event.TIMEOUT, refused.primitive());
            return defaultValue;
        } catch (Exception thrown) {
            requester.raise(Event.UNCAUGHT_EXCEPTION, RemotePrimitiveException.classNameOf(thrown));
            return defaultValue;
        }
    }

    @Override
    public <T> T readAttribute(AgentImplementation owner, String attribute, T defaultValue, Supplier<T> read) {
        if (owner == null) {
            return nullAgent(defaultValue);
        }
        if (!mission.agentOf(owner).permitsAttribute(this, attribute, PermeabilityState.READ)) {
            raise(Event.FORBIDDEN_ACCESS, attribute);
            return defaultValue;
        }
        return read.get();
    }

    @Override
    public boolean writeAttribute(AgentImplementation owner, String attribute, Runnable write) {
        if (owner == null) {
            nullAgent(null);
            return false;
        }
        if (!mission.agentOf(owner).permitsAttribute(this, attribute, PermeabilityState.WRITE)) {
            raise(Event.FORBIDDEN_ACCESS, attribute);
            return false;
        }
        write.run();
        return true;
    }

    /** Whether the current state lets an agent outside the mission read {@code attribute} (its r bit for o). */
    boolean othersMayRead(String attribute) {
        return Permeability.allows(permeability.current(), permeability.attributeId(attribute),
                PermeabilityState.Requester.OTHER, PermeabilityState.READ);
    }

    private boolean permitsAttribute(Agent requester, String attribute, int permission) {
        return Permeability.allows(permeability.current(), permeability.attributeId(attribute),
                relationOf(requester, permeability.isStaticAttribute(attribute)), permission);
    }

    @Override
    public void setAcceptState(String name) {
        PermeabilityState state = permeability.find(name).orElse(null);
        if (state == null) {
            uncaughtException(new IllegalArgumentException("no permeability state " + name));
            return;
        }
        permeability.set(state);
        mission.changes().advance();
    }

    @Override
    public String getAcceptState() {
        return permeability.currentName();
    }

    String acceptStateName() {
        return permeability.currentName();
    }

    @Override
    public String getAcceptState(AgentImplementation agent) {
        if (agent == null) {
            return nullAgent("");
        }
        return mission.agentOf(agent).permeability.currentName();
    }

    @Override
    public boolean waitFor(String state) {
        return waitFor(state, -1);
    }

    @Override
    public boolean waitFor(String state, long ms) {
        atCallBefore();
        progress++;
        PermeabilityState attentiveTo = permeability.find(state).orElse(null);
        if (attentiveTo == null) {
            uncaughtException(new IllegalArgumentException("no permeability state " + state));
            return yieldIfSliceUsed();
        }
        PendingInvocation allowed = firstAllowedBy(attentiveTo);
        if (allowed != null) {
            invocations.remove(allowed);
            serve(allowed);
            return yieldIfSliceUsed();
        }
        long ticket = prepareToPark();
        attentiveState = attentiveTo;
        attentiveTicket.set(ticket);
        if (ms >= 0) {
            mission.outsideWakeUpStarted();
            mission.scheduler().scheduleAfter(ms, () -> {
                if (attentiveTicket.compareAndSet(ticket, 0)) {
                    unpark(ticket);
                }
                mission.outsideWakeUpEnded();
            });
        }
        // The slice ends PARKED and then serves what the state allows (serveIfPending).
        return false;
    }

    // ---- runtime side --------------------------------------------------------------------------

    /**
     * Queues an external invocation of one of this agent's primitives (MASL §9). A running agent
     * runs it at its next step boundary or loop iteration; a blocked or finished one has it run on
     * its behalf at once (§5). An invocation runs the callee's primitive only: served on behalf of
     * a parked agent, it must not use the agent's {@link AgentContext}, whose memberships other
     * agents may be changing meanwhile.
     */
    void submitInvocation(PendingInvocation invocation) {
        // Queueing one for an idle agent wakes it, for the deadlock watchdog (Mission): counted first.
        mission.countSchedule();
        invocations.add(invocation);
        serveIfPending();
        mission.changes().advance();
    }

    /**
     * Queues an external invocation as {@link #submitInvocation} does, but if the agent is blocked or
     * finished, serves the pending invocations at once on the calling thread, through the same
     * {@code SERVING} state a serving slice takes: for requesters outside the mission (the JADE
     * bridge's message thread), which then answer without a hop to the agent's thread. The
     * invocation must not wait for the calling thread.
     */
    void submitInvocationServingInline(PendingInvocation invocation) {
        mission.countSchedule();
        invocations.add(invocation);
        // Once the mission has ended, an invocation is never run: its scheduler would not run a serving slice either.
        if (!mission.hasEnded() && claimServing()) {
            serveWhileBlocked();
        }
        mission.changes().advance();
    }

    /**
     * Makes this agent perceive a system event ({@code timeout}, {@code uncaught_exception},
     * {@code forbidden_access}: local to it, §8). Safe from any thread, for instance from an agent
     * serving an invocation that this agent made.
     */
    void raise(Event systemEvent, String message) {
        if (!systemEvent.isSystemEvent()) {
            throw new IllegalArgumentException(systemEvent + " is not a system event");
        }
        mission.trace().record(new TraceEvent.EventEmitted(now(), id, systemEvent.name(), null, message, 1, source()));
        perceive(new EventOccurrence(systemEvent, message, id));
    }

    /** Perceives an occurrence (§8): from any thread, never blocks; wakes a parked busy-wait (§5). */
    void perceive(EventOccurrence occurrence) {
        events.offer(occurrence);
        // A stale ticket (the agent has woken since, or parks elsewhere) is ignored by unpark.
        long ticket = busyWaitTicket;
        if (ticket != 0) {
            unpark(ticket);
        }
    }

    /**
     * Step 1 of a boundary (§5, §8): takes every occurrence perceived so far and, if any has a
     * reaction, saves where the boundary continues and redirects the program to the first
     * reaction. Returns whether it did; the boundary call then returns {@code false}.
     */
    private boolean startReactions(boolean barrierDue) {
        if (events.isEmpty()) {
            return false;
        }
        List<EventOccurrence> perceived = events.takeAll();
        List<EntryDefinition> chain = new ArrayList<>(memberships.size());
        for (int i = memberships.size() - 1; i >= 0; i--) {
            chain.add(memberships.get(i).entry.definition());
        }
        ReactionPlan plan = ReactionPlan.of(perceived, chain);
        plan.dropped().forEach(this::traceDropped);
        if (plan.steps().isEmpty()) {
            return false;
        }
        progress++;
        interruptedStatementPc = statementPc;
        interruptedStatementIsLoop = statementIsLoop;
        reacting = new ReactionRun(plan.steps(), program.pc(), barrierDue);
        redirectToNextReaction();
        return true;
    }

    private void redirectToNextReaction() {
        ReactionPlan.Step step = reacting.next();
        Reaction reaction = step.reaction();
        mission.trace().record(new TraceEvent.EventReacted(now(), id,
                step.occurrence().event().name(), reaction.block().name(), reaction.isDefault(),
                sourceOf(interruptedStatementPc, interruptedStatementIsLoop)));
        program.jump(program.reactionPc(reaction));
        suspended = true;
        redirected = true;
    }

    private void traceDropped(EventOccurrence occurrence) {
        mission.trace().record(new TraceEvent.EventDropped(now(), id, occurrence.event().name(), source()));
    }

    /** The mission clock, for trace timestamps. */
    private long now() {
        return mission.scheduler().nanoTime();
    }

    private boolean isReacting() {
        return reacting != null;
    }

    /** A reaction runs in one go (§8): from its start to {@link #endReaction()}, no block operation or boundary. */
    private void requireNoReactionRunning(String what) {
        if (reacting != null) {
            throw new IllegalStateException(describe() + ": " + what + " inside a reaction");
        }
    }

    /** Neither in a reaction, nor between the last one's end and its ending (resume, break, …). */
    private void requireOutsideReaction(String what) {
        requireNoReactionRunning(what);
        if (ending != null) {
            throw new IllegalStateException(describe() + ": " + what
                    + " after endReaction(): a reaction ends with resumeInterrupted, break, restart or reelect");
        }
    }

    private void requireMember(Event event, Entry block) {
        for (Membership membership : memberships) {
            if (membership.entry == block) {
                return;
            }
        }
        throw new IllegalStateException(describe() + " emits " + event + " outside that block");
    }

    /**
     * Step 2 of a boundary, or a serving slice (§5): every pending invocation in order, each run or
     * denied by the current state; while attentive (in {@code wait(state)}), only the first one that
     * state allows, which then ends the wait.
     */
    private void serveInvocations() {
        long attentive = attentiveTicket.get();
        if (attentive != 0) {
            serveAttentively(attentive);
            return;
        }
        PendingInvocation invocation;
        while ((invocation = invocations.poll()) != null) {
            PermeabilityState state = permeability.current();
            if (permits(state, invocation)) {
                serve(invocation);
            } else {
                mission.trace().record(new TraceEvent.InvocationDenied(now(), id, invocation.requesterId(),
                        invocation.primitive(), permeability.currentName(), source()));
                invocation.deny();
            }
        }
    }

    private void serveAttentively(long ticket) {
        PendingInvocation allowed = firstAllowedBy(attentiveState);
        // The timeout of the wait may have won: then the invocation waits for the next boundary.
        if (allowed == null || !attentiveTicket.compareAndSet(ticket, 0)) {
            return;
        }
        invocations.remove(allowed);
        serve(allowed);
        unpark(ticket);
    }

    private void serve(PendingInvocation invocation) {
        mission.trace().record(new TraceEvent.InvocationServed(now(), id, invocation.requesterId(),
                invocation.primitive(), source()));
        invocation.run();
    }

    /** Whether a serving slice has something to run: any pending invocation, or while attentive one it allows. */
    private boolean hasServable() {
        if (invocations.isEmpty()) {
            return false;
        }
        return attentiveTicket.get() == 0 || firstAllowedBy(attentiveState) != null;
    }

    private PendingInvocation firstAllowedBy(PermeabilityState state) {
        for (PendingInvocation invocation : invocations) {
            if (permits(state, invocation)) {
                return invocation;
            }
        }
        return null;
    }

    /** Whether {@code state} of this agent lets the invocation run, its requester's relation decided now (§11). */
    private boolean permits(PermeabilityState state, PendingInvocation invocation) {
        String primitive = invocation.primitive();
        if (primitive == null || state == null) {
            return true;
        }
        // The relation needs the coordinator's lock: decided only when a state's rights depend on it.
        return Permeability.allows(state, permeability.primitiveId(primitive),
                relationOf(invocation.requester(), permeability.isStaticPrimitive(primitive)),
                PermeabilityState.INVOKE);
    }

    /**
     * The requester's digit of the rights (§11), decided at the time of the access: u for this agent,
     * g for an agent whose innermost current block is exactly this agent's, o otherwise. For a static
     * member, a requester of the same type is filtered by u, another by g or o.
     */
    private Requester relationOf(Agent requester, boolean staticMember) {
        if (requester == this) {
            return Requester.SELF;
        }
        if (requester == null) {
            return Requester.OTHER;
        }
        if (staticMember && requester.permeability.type() == permeability.type()) {
            return Requester.SELF;
        }
        boolean sameBlock = mission.coordinator().query(() -> !memberships.isEmpty()
                && !requester.memberships.isEmpty() && innermost().entry == requester.innermost().entry);
        return sameBlock ? Requester.GROUP : Requester.OTHER;
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

    public Membership innermost() {
        return memberships.get(memberships.size() - 1);
    }

    /** Held by an entry or exit barrier: then it is active nowhere (§6.3). */
    public boolean isHeld() {
        return !memberships.isEmpty() && innermost().status != Membership.Status.ACTIVE;
    }

    /** The current runtime call comes after {@code pc} was set to the case that follows its own. */
    private void atCallBefore() {
        statementPc = program.pc() - 1;
        statementIsLoop = false;
    }

    /** The current runtime call is made from the case {@code pc} names. */
    private void atCurrentCase() {
        statementPc = program.pc();
        statementIsLoop = false;
    }

    /** The current runtime call is a loop's iteration, made from its head, the case {@code pc} names. */
    private void atLoopHead() {
        statementPc = program.pc();
        statementIsLoop = true;
    }

    /**
     * The MASL statement the agent is at ({@code "e6.masl:14: synchronous entry turn (…)"}), or null
     * if its program does not say: the last statement of the case making the current call (a loop's
     * own statement at its head), or of the nearest case before it that has one.
     */
    public String source() {
        return sourceOf(statementPc, statementIsLoop);
    }

    private String sourceOf(int statement, boolean loopHead) {
        String source = loopHead ? program.sourceAt(statement) : program.sourceOfCallIn(statement);
        for (int pc = statement - 1; source == null && pc >= 0 && pc > statement - 4; pc--) {
            source = program.sourceOfCallIn(pc);
        }
        return source;
    }

    public String describe() {
        String source = source();
        return "agent " + name + " (" + id + ") at pc " + program.pc() + (source == null ? "" : " (" + source + ")");
    }

    @Override
    public String toString() {
        return name;
    }
}
