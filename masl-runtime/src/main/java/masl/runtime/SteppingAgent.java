package masl.runtime;

import masl.runtime.descriptor.AgentType;
import masl.runtime.entry.SynchronisationBarrier;
import masl.runtime.event.EventOccurrence;
import masl.runtime.event.ReactionPlan;
import masl.runtime.event.ReactionRun;
import masl.runtime.invocation.ServingAgent;
import masl.runtime.trace.TraceEvent;

/**
 * The boundaries of an agent's program (MASL §5, §8): step boundaries, the end of a block or
 * e-sequence, loop iterations and busy-waits, where the layers of the agent meet. Each boundary
 * takes, in this order, the events perceived ({@link #startReactions}: if any has a reaction, the
 * program is redirected to it and the boundary goes on when the reactions end,
 * {@link #resumeInterrupted()}), the invocations queued ({@link #serveQueuedInvocations()}), then
 * the barrier of the agent's synchronous block ({@code EntryCoordinator.arriveAtBarrier}), and
 * yields if the slice has run its steps. It also knows which MASL statement the agent is at, for
 * the trace. {@link Agent} is the rest of the agent's {@link AgentContext}; this layer is apart so
 * that the boundary's order reads in one place.
 *
 * <p>Confined to the agent's slices, but for what the layers below say of themselves.
 */
abstract class SteppingAgent extends ServingAgent implements AgentContext {

    private static final int BEFORE_EVERY_LOOP = Integer.MIN_VALUE;

    // Confined to the thread running the current slice (successive slices are ordered).
    private long busyWaitEpoch = -1;
    private long busyWaitProgress = -1;
    /**
     * Where the agent's latest step was, which tells the loop iterations that ran no instruction
     * (MASL §5): in a synchronous block such an iteration is itself one instruction, with the full
     * step boundary, barrier included; one that ran an instruction has met the barrier already and
     * adds no step. The runtime sees a loop only at the end of each iteration, where {@code pc} names
     * the loop's head (contract §3.8), and cases are numbered in program order (contract §1.2): a
     * loop's body comes after its head, the code before the loop before it. So it is enough to
     * remember the case after the latest instruction's step boundary, or the loop's head for the end
     * of an iteration: an iteration of the loop at {@code head} ran an instruction exactly when the
     * latest step comes after {@code head} (in its body, or at the head of a loop nested in it, whose
     * iterations each ran an instruction or were one). On the first iteration the latest step is
     * before the loop, on the next ones at its own head. A {@code restart} or {@code reelect} jumps
     * back to the start of a block ({@link #jumpedBack}). A field of the agent, not an object of its
     * own: every loop iteration reads and writes it.
     */
    private int latestStep = BEFORE_EVERY_LOOP;

    SteppingAgent(int id, String name, AgentProgram program, Mission mission, AgentType type) {
        super(id, name, program, mission, type, mission.coordinator(), mission.trace());
    }

    /** This agent as the coordinator and the barriers know it: it is the only subclass. */
    private Agent self() {
        return (Agent) this;
    }

    @Override
    public final boolean stepBoundary() {
        atCallBefore();
        return instructionEnded("a step boundary", null);
    }

    /** The boundary after an instruction (§5), {@code what} and its {@code subject} for the error of one inside a reaction. */
    private boolean instructionEnded(String what, Object subject) {
        requireOutsideReaction(what, subject);
        progress++;
        latestStep = program.pc();
        SynchronisationBarrier barrier = barrierDue();
        if (startReactions(barrier != null)) {
            return false;
        }
        return completeBoundary(barrier);
    }

    /** Steps 2 and 3 of a step boundary (§5): pending invocations, then the barrier if one is due (null: none). */
    private boolean completeBoundary(SynchronisationBarrier barrier) {
        serveQueuedInvocations();
        if (barrier != null && !mission.coordinator().arriveAtBarrier(self(), barrier)) {
            return false;
        }
        return yieldIfSliceUsed();
    }

    @Override
    public final boolean endOfChild(EntryDefinition block) {
        atCallBefore();
        requireAtLevelOf(block.parent(), block);
        return instructionEnded("the end of", block.name());
    }

    @Override
    public final boolean endOfSequence(ESequence sequence) {
        atCallBefore();
        requireAtLevelOf(sequence.parent(), sequence);
        requireOutsideReaction("the end of an e-sequence", null);
        progress++;
        if (startReactions(false)) {
            return false;
        }
        return completeBoundary(null);
    }

    @Override
    public final boolean loopIteration() {
        atLoopHead();
        progress++;
        if (reactionsUnderway && events.isReacting()) {
            return yieldIfSliceUsed();
        }
        SynchronisationBarrier barrier = idleStepDue();
        if (startReactions(barrier != null)) {
            return false;
        }
        return completeBoundary(barrier);
    }

    @Override
    public final boolean busyWaitIteration() {
        atLoopHead();
        if (!events.isReacting()) {
            SynchronisationBarrier barrier = idleStepDue();
            if (barrier != null) {
                return idleBusyWaitStep(barrier);
            }
            // Reactions assign locals: running them is progress, so the next iteration does not park.
            if (startReactions(false)) {
                return false;
            }
            serveQueuedInvocations();
        }
        long epoch = mission.changes().current();
        if (epoch == busyWaitEpoch && progress == busyWaitProgress) {
            parkInBusyWait(epoch);
            return false;
        }
        busyWaitEpoch = epoch;
        busyWaitProgress = progress;
        return yieldIfSliceUsed();
    }

    /**
     * For a program that runs elsewhere (a deployed agent's): what it needs of the runtime to pass
     * its boundaries there, with no request, while nothing arrives ({@link #onBoundaryWork}); null if
     * its next boundary must come here. A boundary passed there is one that here would do nothing but
     * count: no occurrence perceived, no invocation queued, no reaction underway, the mission going
     * on, and no barrier due, which the program's place of its latest step and whether its innermost
     * block is synchronous say there (a step boundary meets the barrier then; a loop iteration that
     * ran no instruction too, {@link #idleStepDue}). Called by the agent's slice.
     */
    final DeployedPrograms.AtRest boundariesAtRest() {
        if (reactionsUnderway || eventsPending() || invocationsQueued || halted()) {
            return null;
        }
        return new DeployedPrograms.AtRest(latestStep, barrierDue != null);
    }

    /**
     * {@code count} boundaries the program passed elsewhere ({@link #boundariesAtRest}), its latest
     * step then at {@code latest}: counted as the runtime counts its own.
     */
    final void boundariesPassedElsewhere(long count, int latest) {
        progress += count;
        latestStep = latest;
    }

    /**
     * The barrier the iteration ending here meets as an instruction of its own (§5): that of the
     * innermost block, if it is synchronous and the iteration ran no instruction; else null. Called
     * at a loop's head, where {@link #atLoopHead} has set {@link #statementPc} to it.
     */
    private SynchronisationBarrier idleStepDue() {
        int head = statementPc;
        boolean idle = latestStep <= head;
        latestStep = head;
        return idle ? barrierDue() : null;
    }

    /** A {@code restart} or {@code reelect}: the program goes back to the start of a block, and meets its loops afresh. */
    final void jumpedBack() {
        latestStep = BEFORE_EVERY_LOOP;
    }

    /**
     * An iteration of a busy-wait that ran no instruction, in a synchronous block: one instruction
     * (§5), so events, invocations, then the barrier. Unless the step would change nothing: if
     * nothing the agent can observe has changed since its previous busy-wait iteration, it ran no
     * instruction or reaction since, and no other participant has arrived at the barrier in this
     * phase, the agent parks until a change or an arrival, and iterates again then. A lone member
     * would otherwise trip its own barrier again and again on a core of its own, and members that
     * all wait so would trip it for each other; parked, they are idle for the deadlock watchdog. Its
     * arrival only comes later in the phase: the others wait for it as for a member still running
     * its instruction, and their first arrival wakes it.
     */
    private boolean idleBusyWaitStep(SynchronisationBarrier barrier) {
        if (startReactions(true)) {
            return false;
        }
        serveQueuedInvocations();
        long epoch = mission.changes().current();
        if (epoch == busyWaitEpoch && progress == busyWaitProgress && !barrier.hasArrivals()) {
            barrier.wakeOnArrival(self(), parkInBusyWait(epoch));
            return false;
        }
        busyWaitEpoch = epoch;
        busyWaitProgress = progress;
        return completeBoundary(barrier);
    }

    /** Parks the agent until something it can observe changes (§5); returns the park's ticket. */
    private long parkInBusyWait(long epoch) {
        long ticket = mission.changes().parkUntilChanged(self(), epoch);
        busyWaitPark = true;
        busyWaitTicket = ticket;
        // An emitter that pushed before the ticket was published has not woken us: wake ourselves.
        if (!events.isReacting() && !events.nothingPerceived()) {
            unpark(ticket);
        }
        return ticket;
    }

    @Override
    public final boolean resumeInterrupted() {
        ReactionRun ended = events.takeEnding();
        reactionsUnderway = false;
        if (ended == null) {
            throw new IllegalStateException(describe() + ": resume without a reaction that just ended");
        }
        program.jump(ended.interruptedPc());
        statementPc = ended.statementPc();
        statementIsLoop = ended.statementIsLoop();
        return completeBoundary(ended.barrierDue() ? barrierDue() : null);
    }

    @Override
    protected final void redirectToNextReaction() {
        ReactionRun processing = events.reacting();
        ReactionPlan.Step step = processing.next();
        Reaction reaction = step.reaction();
        mission.trace().record(new TraceEvent.EventReacted(now(), id,
                step.occurrence().event().name(), reaction.block().name(), reaction.isDefault(),
                sourceOf(processing.statementPc(), processing.statementIsLoop())));
        program.jump(program.reactionPc(reaction));
        suspended = true;
        redirected = true;
    }

    @Override
    protected final void traceDropped(EventOccurrence occurrence) {
        mission.trace().record(new TraceEvent.EventDropped(now(), id, occurrence.event().name(), source()));
    }

    /** The mission clock, for trace timestamps. */
    long now() {
        return mission.scheduler().nanoTime();
    }

    /**
     * The MASL statement the agent is at ({@code "e6.masl:14: synchronous entry turn (…)"}), or null
     * if its program does not say: the last statement of the case making the current call (a loop's
     * own statement at its head), or of the nearest case before it that has one.
     */
    @Override
    public final String source() {
        return sourceOf(statementPc, statementIsLoop);
    }

    /**
     * This agent invoked {@code callee}'s {@code primitive} from the case {@code pc} of its program,
     * and {@code callee} served it, both where their programs run (a deployed team's container):
     * traced as the runtime traces an invocation it queues and serves.
     */
    final void invokedElsewhere(SteppingAgent callee, String primitive, int pc) {
        mission.trace().record(new TraceEvent.InvocationMade(now(), id(), callee.id(), primitive, sourceOf(pc, false)));
        mission.trace().record(new TraceEvent.InvocationServed(now(), callee.id(), id(), primitive, callee.source()));
    }

    private String sourceOf(int statement, boolean loopHead) {
        String source = loopHead ? program.sourceAt(statement) : program.sourceOfCallIn(statement);
        for (int pc = statement - 1; source == null && pc >= 0 && pc > statement - 4; pc--) {
            source = program.sourceOfCallIn(pc);
        }
        return source;
    }
}
