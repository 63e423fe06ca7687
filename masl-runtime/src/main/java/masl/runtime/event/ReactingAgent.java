package masl.runtime.event;

import java.util.function.Consumer;
import masl.runtime.AgentProgram;
import masl.runtime.Event;
import masl.runtime.Mission;
import masl.runtime.entry.MemberAgent;

/**
 * The event side of an agent ({@code masl.runtime.Agent}, MASL §8): the boundary of its event
 * queue, where occurrences come in from any thread, and the reactions they start at its step
 * boundaries. A layer of the agent, not an object of its own, for the reason
 * {@code scheduling.ScheduledAgent} gives: every step boundary asks {@link #reactionsUnderway} and
 * {@code eventsPerceived}, and in lock-step these two fields are all it reads of events.
 *
 * <p>If an occurrence perceived by the boundary has a reaction, the agent <em>redirects</em> its
 * program to it ({@link #redirectToNextReaction()}): the boundary call returns {@code false}, the
 * slice resumes the program at once. Each reaction ends with {@link #endReaction()}, which
 * redirects to the next one or lets the last one apply its ending.
 *
 * <p><b>Memory consistency effects.</b> Actions of a thread before it makes the agent
 * {@linkplain #perceive perceive} an occurrence happen-before the actions of the agent's boundary
 * that takes it (the queue's push is a compare-and-set, the boundary's take a get-and-set; the
 * {@code eventsPerceived} flag is volatile and written after the push). An occurrence whose flag
 * a boundary does not see yet counts as perceived after that boundary. Everything else here is
 * confined to the agent's slices.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public abstract class ReactingAgent extends MemberAgent {

    protected final EventPlanner events = new EventPlanner();
    // Made once: the hot paths that take it allocate nothing.
    protected final Consumer<EventOccurrence> dropped = this::traceDropped;
    /** The ticket of the agent's latest busy-wait park: an event perceived then wakes it (§5). */
    protected volatile long busyWaitTicket;
    /**
     * Set after an occurrence is perceived; cleared by the agent's own boundary before it takes the
     * occurrences. A boundary that finds it clear reads no event queue: the queue is objects of their
     * own, cache lines an agent-step would otherwise fetch for nothing.
     */
    private volatile boolean eventsPerceived;
    /**
     * From the start of an event processing to its ending (resumed or abandoned) or the program's
     * death: false says that {@link #events} has no reaction running or ending, without reading it.
     * Every step boundary and loop iteration asks; in lock-step, this field saves an agent-step the
     * cache line of another object. Confined to the agent's slices.
     */
    protected boolean reactionsUnderway;

    protected ReactingAgent(int id, String name, AgentProgram program, Mission mission) {
        super(id, name, program, mission);
    }

    /** Sets the program's pc to the next reaction of the processing underway, and records it. */
    protected abstract void redirectToNextReaction();

    /** Records that an occurrence was dropped without a reaction. */
    protected abstract void traceDropped(EventOccurrence occurrence);

    /** Perceives an occurrence (§8): from any thread, never blocks; wakes a parked busy-wait (§5). */
    public final void perceive(EventOccurrence occurrence) {
        events.perceive(occurrence);
        eventsPerceived = true;
        boundaryWorkArrived();
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
    protected final boolean startReactions(boolean barrierDue) {
        // An occurrence whose flag this does not see yet is perceived after this boundary.
        if (!eventsPerceived) {
            return false;
        }
        eventsPerceived = false;
        if (events.nothingPerceived()) {
            return false;
        }
        if (events.start(chainInnermostFirst(), program.pc(), barrierDue, statementPc, statementIsLoop, dropped) == null) {
            return false;
        }
        reactionsUnderway = true;
        progress++;
        redirectToNextReaction();
        return true;
    }

    /** Whether an occurrence was perceived that no boundary has taken yet. */
    protected final boolean eventsPending() {
        return eventsPerceived;
    }

    /** The end of a reaction (AgentContext): false if the program was redirected to the next one. */
    public final boolean endReaction() {
        if (!events.isReacting()) {
            throw new IllegalStateException(describe() + ": endReaction outside a reaction");
        }
        if (!events.endReaction()) {
            redirectToNextReaction();
            return false;
        }
        return true;
    }

    /** Drops the occurrences perceived and not yet reacted to (AgentContext), from a reaction. */
    public final void clearEvents() {
        if (!events.isReacting()) {
            throw new IllegalStateException(describe() + ": clearEvents outside a reaction");
        }
        events.clear(dropped);
    }

    /** The message of the latest occurrence of {@code event} reacted to (AgentContext). */
    public final String messageOf(Event event) {
        return events.messageOf(event);
    }

    /** The processing's ending is a break, restart or reelect: nothing is underway any more. */
    protected final void abandonEnding() {
        events.abandonEnding();
        reactionsUnderway = false;
    }

    /** A reaction runs in one go (§8): from its start to {@link #endReaction()}, no block operation or boundary. */
    protected final void requireNoReactionRunning(String what) {
        if (reactionsUnderway && events.isReacting()) {
            throw new IllegalStateException(describe() + ": " + what + " inside a reaction");
        }
    }

    /**
     * Neither in a reaction, nor between the last one's end and its ending (resume, break, …):
     * {@code what}, followed by {@code subject} unless it is null, names the operation in the error.
     * The two are joined only for the error: a boundary or a block's entry that joined them each time
     * built a string (and lower-cased a block's mode) per agent-step.
     */
    protected final void requireOutsideReaction(String what, Object subject) {
        if (!reactionsUnderway) {
            return;
        }
        String operation = subject == null ? what : what + " " + subject;
        requireNoReactionRunning(operation);
        if (events.isEnding()) {
            throw new IllegalStateException(describe() + ": " + operation
                    + " after endReaction(): a reaction ends with resumeInterrupted, break, restart or reelect");
        }
    }
}
