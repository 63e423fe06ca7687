package masl.runtime;

import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.function.Supplier;
import masl.runtime.descriptor.AgentType;
import masl.runtime.entry.Entry;
import masl.runtime.entry.EntryCoordinator;
import masl.runtime.entry.MemberAgent;
import masl.runtime.event.Emitter;
import masl.runtime.event.EventOccurrence;
import masl.runtime.event.ReactingAgent;
import masl.runtime.invocation.Countermeasures;
import masl.runtime.invocation.Invoker;
import masl.runtime.invocation.PendingInvocation;
import masl.runtime.invocation.Permeability;
import masl.runtime.invocation.PrimitiveCalls;
import masl.runtime.invocation.ServingAgent;
import masl.runtime.scheduling.RunState;
import masl.runtime.scheduling.ScheduledAgent;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.TraceEvent;

/**
 * A MASL agent at run time: an active object with its own program counter (in its
 * {@link AgentProgram}), memberships, event and invocation queues, run slice by slice by the
 * mission's {@link Scheduler}. It is the {@link AgentContext} its program calls. Its state is in
 * layers, superclasses each of its package, so that an agent-step in lock-step reads the fields of
 * one object (docs/decisions.md, "An agent in layers"):
 *
 * <ul>
 * <li><b>Scheduling</b> ({@link ScheduledAgent}, {@link RunState}): {@code SCHEDULED → RUNNING →
 * PARKED → SCHEDULED}, with park tickets; a slice runs the program ({@link #runSlice}), a wait
 * issues a ticket ({@link #prepareToPark()}) and whoever ends it calls {@link #unpark(long)} with
 * it. An invocation queued for a parked or finished agent turns it {@code SERVING}: a slice then
 * serves it on the agent's behalf without running its program (MASL §5).</li>
 * <li><b>Blocks</b> ({@link MemberAgent}): the memberships and the barrier arrival, which the
 * {@link EntryCoordinator} changes.</li>
 * <li><b>Events</b> ({@link ReactingAgent}, MASL §8): emitters push occurrences from any thread and
 * unpark the agent if it is parked in a busy-wait (§5). At a boundary the agent plans the
 * reactions and <em>redirects</em> its program to the first one; each ends with
 * {@link #endReaction()}, and the last one applies its ending (§8: the last reaction decides):
 * {@link #resumeInterrupted()}, or a break, restart or reelect. What the agent emits and raises
 * goes through its {@link Emitter}.</li>
 * <li><b>Invocations</b> ({@link ServingAgent}, MASL §9, §11): an external invocation waits in
 * the callee's queue until the callee's next boundary, or a serving slice, serves it, if its
 * {@link Permeability} lets the requester in; in {@code wait(state)} the agent serves only what
 * that state allows. Invocations between the mission's agents are served by a scheduled slice, so
 * that the order of slices stays the scheduler's (a seeded run replays); one from outside the
 * mission may be served inline ({@link #submitInvocationServingInline}, the JADE bridge's FIPA
 * requests). What the agent requests of others (invocations, launches, attributes, its accept
 * state, the {@link Countermeasures} its launches arm) is its {@link Invoker}'s.</li>
 * <li><b>Boundaries</b> ({@link SteppingAgent}, MASL §5): where these meet, in their order.</li>
 * </ul>
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Agent extends SteppingAgent implements AgentContext {

    public final AgentImplementation implementation;
    private final Invoker invoker;
    private final Emitter emitter;
    /** Why the agent's program is over from outside ({@link #failFromOutside}), or null. */
    private volatile Throwable failedFromOutside;

    Agent(int id, String name, AgentImplementation implementation, AgentType type, AgentProgram program,
            Mission mission) {
        super(id, name, program, mission, type);
        this.implementation = implementation;
        PrivateSide side = new PrivateSide();
        this.invoker = new Invoker(this, permeability, side);
        this.emitter = new Emitter(this, side);
    }

    // ---- AgentTask -----------------------------------------------------------------------------

    @Override
    public void runSlice() {
        if (isServing()) {
            serveWhileBlocked();
            return;
        }
        if (!startSlice()) {
            // A runtime bug, not the program's: fail the mission rather than the scheduler's thread.
            mission.agentFailed(this, new IllegalStateException(describe() + " scheduled in state " + describeState()));
            return;
        }
        runProgram();
    }

    @Override
    public boolean runSliceWoken(long ticket) {
        if (!resumeParked(ticket)) {
            return false;
        }
        runProgram();
        return true;
    }

    /**
     * The agent's program is over for a reason outside it: the agent dies with {@code cause} as if
     * its program had thrown it, in a slice of its own, so that it fires its countermeasures and leaves
     * every block as any failed agent does, the barriers it was counted in no longer waiting for it.
     * For a program that runs elsewhere (a deployed agent's, whose container is lost): a parked agent
     * (at a barrier, in a wait, a sleep, a blocked entry) is woken for it now, one whose slice runs
     * dies when the slice ends, or at its next park. The first cause given counts. Any thread.
     *
     * <p><b>Memory consistency effects.</b> The cause is written before the pending ticket is read,
     * and the slice reads it after its park's compare-and-set: either this call finds the park's
     * ticket and ends it, or the slice finds the cause and ends its own park.
     */
    public void failFromOutside(Throwable cause) {
        if (failedFromOutside == null) {
            failedFromOutside = cause;
        }
        if (finished || halted()) {
            return;
        }
        mission.outsideWakeUpStarted();
        try {
            unpark(pendingTicket());
        } finally {
            mission.outsideWakeUpEnded();
        }
    }

    /** The slice of a running agent: its program until it suspends or finishes, then where it goes. */
    private void runProgram() {
        stepsThisSlice = 0;
        Throwable outside = failedFromOutside;
        if (outside != null) {
            die(outside);
            return;
        }
        try {
            do {
                suspended = false;
                redirected = false;
                program.resume(this);
            } while (redirected && !finished);
        } catch (Throwable failure) {
            if (failure instanceof OutOfMemoryError) {
                // Before die() allocates: the reserve released, the mission failed.
                MemoryReserve.exhausted();
            }
            die(failure);
            return;
        }
        if (finished) {
            end();
            mission.agentFinished(this);
            serveIfPending();
        } else if (!suspended) {
            die(new IllegalStateException(describe() + ": resume returned without a suspension or finish()"));
        } else if (!endSliceParked(false)) {
            mission.countSchedule();
            reschedule();
            mission.scheduler().schedule(this);
        } else if (failedFromOutside != null) {
            // Failed from outside while the slice ran: the park just made may be one nobody ends.
            unpark(pendingTicket());
        }
    }

    /**
     * Serves the pending invocations of a blocked (or finished) agent, nothing else, then returns it
     * to where it was: in a serving slice, or on the submitting thread for an invocation served inline.
     */
    private void serveWhileBlocked() {
        try {
            invocations.serveAll();
        } catch (Throwable failure) {
            end();
            mission.agentFailed(this, failure);
            return;
        }
        if (finished) {
            done();
            // An invocation queued after the queue was drained found the agent SERVING: serve it too.
            serveIfPending();
        } else if (!endSliceParked(true)) {
            mission.countSchedule();
            reschedule();
            mission.scheduler().schedule(this);
        }
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
            events.abandon();
            reactionsUnderway = false;
            invoker.fireCountermeasures(0);
            mission.coordinator().leaveAll(this);
        } catch (RuntimeException leaving) {
            failure.addSuppressed(leaving);
            mission.agentFailed(this, failure);
        }
        end();
        mission.agentDied(this, failure);
        serveIfPending();
    }

    /**
     * Reads the state a slice of this agent reads first, bringing it into the calling core's cache.
     * A thread about to wake and run a batch of agents calls it on each of them first: their cache
     * misses then overlap, instead of coming one after the other inside each slice. At 100,000
     * agents, most of an agent-step was that wait; at a few thousand, the state is still
     * in the core's cache, and a chunk's wake-up skips it ({@code ArrivalCombiner.WARM_FROM}). The
     * result means nothing; the caller keeps it (a sum stored in a field) so that the compiler
     * cannot drop the reads.
     */
    public int warmUp() {
        return program.pc() + (barrierDue == null ? 0 : 1) + (reactionsUnderway ? 1 : 0) + stepsThisSlice
                + (suspended ? 1 : 0) + (int) progress + (int) pendingTicket();
    }

    // ---- AgentContext --------------------------------------------------------------------------

    @Override
    public int proxyId() {
        return id;
    }

    @Override
    public Arrival enter(EntryDefinition block, boolean test) {
        atCallBefore();
        requireOutsideReaction("arriving at", block);
        return mission.coordinator().enter(this, mission.entry(block), test);
    }

    @Override
    public boolean leave(EntryDefinition block) {
        atCallBefore();
        requireOutsideReaction("leaving", block);
        invoker.fireCountermeasures(memberships.size() - 1);
        return mission.coordinator().leaveAtEnd(this, mission.entry(block));
    }

    @Override
    public void breakOut(EntryDefinition outermost) {
        atCurrentCase();
        requireNoReactionRunning("break");
        abandonEnding();
        invoker.fireCountermeasures(depthOf(outermost));
        mission.coordinator().leaveUpTo(this, mission.entry(outermost), LeaveCause.BREAK);
    }

    @Override
    public void reelect(EntryDefinition block) {
        atCurrentCase();
        requireNoReactionRunning("reelect");
        abandonEnding();
        invoker.fireCountermeasures(depthOf(block));
        mission.coordinator().leaveUpTo(this, mission.entry(block), LeaveCause.REELECT);
        jumpedBack();
    }

    @Override
    public void restart(EntryDefinition block) {
        atCurrentCase();
        requireNoReactionRunning("restart");
        abandonEnding();
        invoker.fireCountermeasures(depthOf(block) + 1);
        mission.coordinator().leaveUpTo(this, mission.entry(block), LeaveCause.RESTART);
        jumpedBack();
    }

    @Override
    public Entry entry(EntryDefinition block) {
        return mission.entry(block);
    }

    @Override
    public void emit(Event event) {
        emit(event, "");
    }

    @Override
    public void emit(Event event, String message) {
        emitter.emit(event, message);
    }

    @Override
    public void uncaughtException(Throwable thrown) {
        atCurrentCase();
        emit(Event.UNCAUGHT_EXCEPTION, RemotePrimitiveException.classNameOf(thrown));
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
        return invoker.invoke(callee, primitive, defaultValue, call);
    }

    @Override
    public <T> T invokeSelf(String primitive, T defaultValue, Callable<T> call) {
        return invoker.invokeSelf(primitive, defaultValue, call);
    }

    @Override
    public <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call) {
        return launch(callee, primitive, defaultValue, call, null, null);
    }

    @Override
    public <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue,
            Callable<T> call, String countermeasure, Callable<?> countermeasureCall) {
        return invoker.launch(callee, primitive, defaultValue, call, countermeasure, countermeasureCall);
    }

    @Override
    public Label newLabel() {
        return new Label(mission.changes());
    }

    @Override
    public <T> T readAttribute(AgentImplementation owner, String attribute, T defaultValue, Supplier<T> read) {
        return invoker.readAttribute(owner, attribute, defaultValue, read);
    }

    @Override
    public boolean writeAttribute(AgentImplementation owner, String attribute, Runnable write) {
        return invoker.writeAttribute(owner, attribute, write);
    }

    @Override
    public void setAcceptState(String name) {
        invoker.setAcceptState(name);
    }

    @Override
    public String getAcceptState(AgentImplementation agent) {
        return invoker.getAcceptState(agent);
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
        queue(invocation);
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
        queue(invocation);
        // Once the mission has ended, an invocation is never run: its scheduler would not run a serving slice either.
        if (!mission.hasEnded() && claimServing()) {
            serveWhileBlocked();
        }
        mission.changes().advance();
    }

    /** Makes this agent perceive a system event ({@link Emitter#raise}); safe from any thread. */
    void raise(Event systemEvent, String message) {
        emitter.raise(systemEvent, message);
    }

    @Override
    public String describe() {
        String source = source();
        return "agent " + name + " (" + id + ") at pc " + program.pc() + (source == null ? "" : " (" + source + ")");
    }

    @Override
    protected boolean halted() {
        return mission.halted();
    }

    /** The agent's private side its {@link Invoker} and {@link Emitter} need: kept off the public one. */
    private final class PrivateSide implements Invoker.Site, Emitter.Site {

        @Override
        public void atCurrentCase() {
            Agent.this.atCurrentCase();
        }

        @Override
        public long now() {
            return Agent.this.now();
        }

        @Override
        public void record(TraceEvent event) {
            mission.trace().record(event);
        }

        @Override
        public Agent agentOf(AgentImplementation implementation) {
            return mission.agentOf(implementation);
        }

        @Override
        public void deliver(Agent receiver, EventOccurrence occurrence) {
            receiver.perceive(occurrence);
        }

        @Override
        public void raise(Event systemEvent, String message) {
            Agent.this.raise(systemEvent, message);
        }

        @Override
        public void submit(Agent target, PendingInvocation invocation) {
            target.submitInvocation(invocation);
        }

        @Override
        public <T> T runFor(String primitive, Callable<T> call, T defaultValue) {
            try {
                return mission.primitiveCalls().call(call);
            } catch (PrimitiveCalls.TimedOut late) {
                Agent.this.raise(Event.TIMEOUT, primitive);
                return defaultValue;
            } catch (InvocationRefusedException refused) {
                Agent.this.raise(Event.TIMEOUT, refused.primitive());
                return defaultValue;
            } catch (Exception thrown) {
                Agent.this.raise(Event.UNCAUGHT_EXCEPTION, RemotePrimitiveException.classNameOf(thrown));
                return defaultValue;
            }
        }

        @Override
        public void runAsynchronously(Runnable body) {
            mission.runAsynchronously(Agent.this, body);
        }

        @Override
        public void changed() {
            mission.changes().advance();
        }
    }
}
