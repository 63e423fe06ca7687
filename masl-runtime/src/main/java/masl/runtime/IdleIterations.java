package masl.runtime;

/**
 * Which loop iterations of an agent ran no instruction (MASL §5): in a synchronous block such an
 * iteration is itself one instruction, with the full step boundary, barrier included; one that
 * ran an instruction has met the barrier already and adds no step.
 *
 * <p>The runtime sees a loop only at the end of each iteration, where {@code pc} names the loop's
 * head (contract §3.8), and cases are numbered in program order (contract §1.2): a loop's body
 * comes after its head, the code before the loop before it. So it is enough to remember where the
 * agent's latest step was: the case after the instruction, for an instruction's step boundary; the
 * loop's head, for the end of an iteration. An iteration of the loop at {@code head} ran an
 * instruction exactly when the latest step comes after {@code head}: in its body, or at the head
 * of a loop nested in it, whose iterations each ran an instruction or were one. On the first
 * iteration the latest step is before the loop, on the next ones at its own head. A {@code restart}
 * or {@code reelect} jumps back to the start of a block: a loop the agent reaches again after it
 * starts afresh.
 *
 * <p>Confined to the agent's slices.
 */
final class IdleIterations {

    private static final int BEFORE_EVERY_LOOP = Integer.MIN_VALUE;

    private int latestStep = BEFORE_EVERY_LOOP;

    /** The step boundary of an instruction; {@code pc} names the case after it. */
    void stepped(int pc) {
        latestStep = pc;
    }

    /** A {@code restart} or {@code reelect}: the program goes back to the start of a block. */
    void jumpedBack() {
        latestStep = BEFORE_EVERY_LOOP;
    }

    /** Where the agent's latest step was, as {@link #endIteration} compares it: for a program that runs elsewhere. */
    int latestStep() {
        return latestStep;
    }

    /** Steps and iterations ended elsewhere (a deployed agent's container), the latest step then at {@code latest}. */
    void endedElsewhere(int latest) {
        latestStep = latest;
    }

    /** The end of an iteration of the loop whose head is the case {@code head}: true if it ran no instruction. */
    boolean endIteration(int head) {
        boolean idle = latestStep <= head;
        latestStep = head;
        return idle;
    }
}
