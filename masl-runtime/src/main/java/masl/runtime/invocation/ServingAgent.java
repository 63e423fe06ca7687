package masl.runtime.invocation;

import java.util.function.BooleanSupplier;
import masl.runtime.AgentProgram;
import masl.runtime.Mission;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.entry.EntryCoordinator;
import masl.runtime.event.ReactingAgent;
import masl.runtime.trace.Trace;

/**
 * The invocation side of an agent ({@code masl.runtime.Agent}, MASL §9, §11): the queue of external
 * invocations of its primitives, who serves them and when, and its {@link Permeability}, which
 * decides, when one is served, whether the current state lets its requester in. A layer of the
 * agent, not an object of its own, for the reason {@code scheduling.ScheduledAgent} gives: every
 * step boundary and the end of every slice ask {@link #invocationsQueued}.
 *
 * <p>An invocation waits in the queue until the agent's next boundary
 * ({@link #serveQueuedInvocations()}), or, if the agent is blocked or done, a serving slice
 * ({@link #serveIfPending()}, see {@link masl.runtime.scheduling.RunState}) serves it on its behalf
 * without running its program (§5). In {@code wait(state)} the agent is <em>attentive</em>
 * ({@link #waitFor(String, long)}): it serves only what that state allows, and the first such
 * invocation ends the wait.
 *
 * <p><b>Memory consistency effects.</b> Actions of a thread before it queues an invocation happen-before
 * the actions of the serving that runs it (the queue is a {@code ConcurrentLinkedQueue}; the
 * {@link #invocationsQueued} flag is volatile and set after the add). A submitter that sets the flag
 * after a boundary cleared it finds the agent running or parked: the end of the slice
 * ({@link #endSliceParked}) reads the flag after the agent turned {@code PARKED} and serves it.
 * Actions of the serving happen-before the agent's next slice (the run state's hand-over).
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public abstract class ServingAgent extends ReactingAgent {

    protected final Permeability permeability;
    protected final InvocationServing invocations;
    // Made once: the hot paths that take them allocate nothing.
    private final BooleanSupplier servable;
    private final BooleanSupplier attentive;
    /**
     * Set after an invocation is queued; cleared by the agent's own boundary before it serves its
     * queue, and set again if some stay queued. A boundary, or the end of a slice, that finds it
     * clear reads no queue: the queue is objects of their own, cache lines an agent-step would
     * otherwise fetch for nothing.
     */
    protected volatile boolean invocationsQueued;

    protected ServingAgent(int id, String name, AgentProgram program, Mission mission, AgentType type,
            EntryCoordinator coordinator, Trace trace) {
        super(id, name, program, mission);
        this.permeability = new Permeability(type, this, coordinator);
        this.invocations = new InvocationServing(this, permeability, trace, mission.scheduler()::nanoTime);
        this.servable = invocations::hasServable;
        this.attentive = invocations::isAttentive;
    }

    /** Reports an exception the program did not catch as the event {@code uncaughtException} (AgentContext). */
    public abstract void uncaughtException(Throwable thrown);

    /**
     * Ends the current slice, running or {@code serving}, {@code → PARKED} unless an unpark came
     * meanwhile (false), then serves the invocations queued while the slice ran, now that the agent
     * is blocked. Parked in {@code wait(state)}, the agent is idle for the deadlock watchdog even
     * with invocations queued (its state may allow none of them), so serving one is a wake-up:
     * pending from before the agent turns {@code PARKED} until it is {@code SERVING} (see
     * {@code DeadlockWatchdog}).
     */
    protected final boolean endSliceParked(boolean serving) {
        // Only the agent's own program makes it attentive, in a wait(state)'s park: no wait can begin
        // during this call.
        boolean attentiveNow = parkAttends && invocations.isAttentive();
        if (attentiveNow) {
            mission.outsideWakeUpStarted();
        }
        try {
            if (!(awayPark && !serving ? parkAway() : park(serving))) {
                return false;
            }
            serveIfPending();
            return true;
        } finally {
            if (attentiveNow) {
                mission.outsideWakeUpEnded();
            }
        }
    }

    /**
     * The agent's own boundary serves what is queued (MASL §5). An invocation queued concurrently
     * whose flag this does not see yet counts as queued after the boundary: its submitter then
     * finds the agent running, and the end of the slice serves it ({@link #serveIfPending}).
     */
    protected final void serveQueuedInvocations() {
        if (invocationsQueued) {
            invocationsQueued = false;
            invocations.serveAll();
            if (!invocations.nothingQueued()) {
                // Kept for later: those wait(state) does not allow.
                invocationsQueued = true;
            }
        }
    }

    /**
     * Schedules a serving slice if invocations wait and the agent is blocked or done. The flag is
     * read after the agent turned {@code PARKED} or {@code DONE}: a submitter that found it running
     * had set the flag before it looked.
     */
    protected final void serveIfPending() {
        if (invocationsQueued && claimServing(servable)) {
            mission.scheduler().schedule(this);
        }
    }

    /** Queues {@code invocation}; whoever queues it then serves it or has it served ({@link #serveIfPending}). */
    protected final void queue(PendingInvocation invocation) {
        invocations.add(invocation);
        invocationsQueued = true;
        boundaryWorkArrived();
    }

    /** Turns the agent {@code SERVING} if it is blocked or done and something it may serve is queued. */
    protected final boolean claimServing() {
        return claimServing(servable);
    }

    /**
     * Idle, for the deadlock watchdog: it runs nothing until it is woken. Parked (waiting for someone
     * else) or done, with no invocation queued (a queued one is always served soon: by a serving
     * slice, or by the agent at its next boundary); parked in {@code wait(state)}, even with
     * invocations queued, which its state may not allow. The queue is read first: the state read
     * after it then says whether the agent was idle at that instant, as nothing the watchdog waits
     * out queues an invocation uncounted (see {@code DeadlockWatchdog}).
     */
    public final boolean isIdle() {
        boolean nothingQueued = invocations.nothingQueued();
        return isIdle(nothingQueued, attentive);
    }

    /** {@code wait(state)} without a time-out (AgentContext). */
    public final boolean waitFor(String state) {
        return waitFor(state, -1);
    }

    /**
     * {@code wait(state, ms)} (AgentContext): serves the first queued invocation {@code state}
     * allows, or parks attentive to it until one comes or {@code ms} pass ({@code ms < 0}: never).
     */
    public final boolean waitFor(String state, long ms) {
        atCallBefore();
        progress++;
        PermeabilityState attentiveTo = permeability.find(state).orElse(null);
        if (attentiveTo == null) {
            uncaughtException(new IllegalArgumentException("no permeability state " + state));
            return yieldIfSliceUsed();
        }
        if (invocations.serveFirstAllowedBy(attentiveTo)) {
            return yieldIfSliceUsed();
        }
        long ticket = prepareToPark();
        invocations.attend(attentiveTo, ticket);
        parkAttends = true;
        if (ms >= 0) {
            mission.outsideWakeUpStarted();
            mission.scheduler().scheduleAfter(ms, () -> {
                if (invocations.stopAttending(ticket)) {
                    unpark(ticket);
                }
                mission.outsideWakeUpEnded();
            });
        }
        // The slice ends PARKED and then serves what the state allows (serveIfPending).
        return false;
    }

    /** Whether the current state lets an agent outside the mission read {@code attribute} (its r bit for o). */
    public final boolean othersMayRead(String attribute) {
        return Permeability.allows(permeability.current(), permeability.attributeId(attribute),
                PermeabilityState.Requester.OTHER, PermeabilityState.READ);
    }

    /** This agent's permeability: its type, current state and what that state allows. */
    public final Permeability permeability() {
        return permeability;
    }

    /** The name of its current state, {@code ""} for a type without states (AgentContext). */
    public final String getAcceptState() {
        return permeability.currentName();
    }
}
