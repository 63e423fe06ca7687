package masl.runtime.event;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;

/**
 * One event processing of one agent as it runs (MASL §8): the reactions still to run, the
 * occurrence being reacted to, and where the interrupted boundary continues once the last reaction
 * resumes. Confined to the agent's slices.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class ReactionRun {

    private final ArrayDeque<ReactionPlan.Step> toRun;
    private final int interruptedPc;
    private final boolean barrierDue;
    private final int statementPc;
    private final boolean statementIsLoop;
    private EventOccurrence current;

    /**
     * @param steps the reactions to run, in order; at least one
     * @param interruptedPc where the interrupted boundary continues
     * @param barrierDue whether that boundary still owes the synchronisation barrier (§5 step 3)
     * @param statementPc the resumption point whose statement the interrupted boundary is at
     * @param statementIsLoop whether that point is a loop's head
     */
    ReactionRun(List<ReactionPlan.Step> steps, int interruptedPc, boolean barrierDue, int statementPc,
            boolean statementIsLoop) {
        this.toRun = new ArrayDeque<>(steps);
        this.interruptedPc = interruptedPc;
        this.barrierDue = barrierDue;
        this.statementPc = statementPc;
        this.statementIsLoop = statementIsLoop;
    }

    public boolean hasNext() {
        return !toRun.isEmpty();
    }

    /** Moves on to the next reaction: its occurrence becomes the one being reacted to. */
    public ReactionPlan.Step next() {
        ReactionPlan.Step step = toRun.poll();
        current = step.occurrence();
        return step;
    }

    /** The occurrence being reacted to. */
    public EventOccurrence current() {
        return current;
    }

    /** {@code clearEvents}: forgets the reactions not run yet and returns their occurrences. */
    List<EventOccurrence> dropRest() {
        List<EventOccurrence> dropped = new ArrayList<>(toRun.size());
        toRun.forEach(step -> dropped.add(step.occurrence()));
        toRun.clear();
        return dropped;
    }

    public int interruptedPc() {
        return interruptedPc;
    }

    public boolean barrierDue() {
        return barrierDue;
    }

    /** The resumption point whose statement the interrupted boundary is at, for trace records. */
    public int statementPc() {
        return statementPc;
    }

    /** Whether {@link #statementPc} is a loop's head. */
    public boolean statementIsLoop() {
        return statementIsLoop;
    }
}
