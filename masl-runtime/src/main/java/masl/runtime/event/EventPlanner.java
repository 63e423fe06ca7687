package masl.runtime.event;

import java.util.List;
import java.util.function.Consumer;
import masl.runtime.EntryDefinition;
import masl.runtime.Event;

/**
 * One agent's events (MASL §8): the occurrences it perceived, and the processing of them that runs.
 *
 * <p>Emitters push occurrences onto the agent's lock-free {@link EventQueue} ({@link #perceive},
 * from any thread). At a step boundary or loop iteration the agent takes the whole queue and plans
 * the reactions ({@link #start}, {@link ReactionPlan}); if there are any, it <em>redirects</em> its
 * program to the first one, remembering where the interrupted boundary continues. Each reaction
 * ends with {@link #endReaction}: the next one, if any, runs; after the last one the processing is
 * <em>ending</em> until its ending (§8: the last reaction decides) is applied: resuming the
 * interrupted boundary ({@link #takeEnding}), or a break, restart or reelect ({@link #abandonEnding}).
 * A reaction runs in one go: from its start to its end, no block operation or boundary.
 *
 * <p>Everything but {@link #perceive} and {@link #nothingPerceived} is confined to the agent's slices.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class EventPlanner {

    private final EventQueue perceived = new EventQueue();
    /** The event processing whose reactions are running; null outside reactions. */
    private ReactionRun reacting;
    /** The processing whose last reaction has ended and is applying its ending (resume, break, …). */
    private ReactionRun ending;

    /** Perceives an occurrence: from any thread, never blocks. */
    public void perceive(EventOccurrence occurrence) {
        perceived.offer(occurrence);
    }

    /** Nothing perceived since the queue was last taken. */
    public boolean nothingPerceived() {
        return perceived.isEmpty();
    }

    /**
     * Takes every occurrence perceived so far and plans the reactions of the blocks of
     * {@code chain} (innermost first); occurrences without one go to {@code dropped}. Returns the
     * processing, its first reaction still to take ({@link ReactionRun#next}), or null if nothing reacts.
     *
     * @param interruptedPc where the interrupted boundary continues
     * @param barrierDue whether that boundary still owes the synchronisation barrier (§5 step 3)
     * @param statementPc the resumption point whose statement the interrupted boundary is at
     * @param statementIsLoop whether that point is a loop's head
     */
    public ReactionRun start(List<EntryDefinition> chain, int interruptedPc, boolean barrierDue, int statementPc,
            boolean statementIsLoop, Consumer<EventOccurrence> dropped) {
        ReactionPlan plan = ReactionPlan.of(perceived.takeAll(), chain);
        plan.dropped().forEach(dropped);
        if (plan.steps().isEmpty()) {
            return null;
        }
        reacting = new ReactionRun(plan.steps(), interruptedPc, barrierDue, statementPc, statementIsLoop);
        return reacting;
    }

    /** The processing whose reactions are running; null outside reactions. */
    public ReactionRun reacting() {
        return reacting;
    }

    public boolean isReacting() {
        return reacting != null;
    }

    /** Between the end of a processing's last reaction and its ending. */
    public boolean isEnding() {
        return ending != null;
    }

    /** {@code getMessageFromEvent(event)}: null unless the occurrence being reacted to is one of {@code event}. */
    public String messageOf(Event event) {
        if (reacting == null || reacting.current().event() != event) {
            return null;
        }
        return reacting.current().message();
    }

    /**
     * The reaction running has ended: false if another one of the processing follows (the caller
     * redirects to {@link ReactionRun#next}); true if it was the last, whose ending the program
     * applies now.
     *
     * @throws IllegalStateException outside a reaction
     */
    public boolean endReaction() {
        if (reacting == null) {
            throw new IllegalStateException("endReaction outside a reaction");
        }
        if (reacting.hasNext()) {
            return false;
        }
        ending = reacting;
        reacting = null;
        return true;
    }

    /** The processing whose ending is to resume the interrupted boundary; null if none just ended. */
    public ReactionRun takeEnding() {
        ReactionRun ended = ending;
        ending = null;
        return ended;
    }

    /** The ending is a break, restart or reelect: the interrupted boundary is not resumed. */
    public void abandonEnding() {
        ending = null;
    }

    /** The program died: no processing runs or ends any more. */
    public void abandon() {
        reacting = null;
        ending = null;
    }

    /**
     * {@code clearEvents}: drops every occurrence not reacted to yet, those of the running
     * processing first, then those perceived since it began, each given to {@code dropped}.
     */
    public void clear(Consumer<EventOccurrence> dropped) {
        reacting.dropRest().forEach(dropped);
        perceived.takeAll().forEach(dropped);
    }
}
