package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * A deployed agent's boundaries that have nothing to do, passed in its container with no message: a
 * loop head, a step boundary that meets no barrier, the end of an e-sequence, while the mission says
 * nothing waits for them. Every message the mission sends to the agent's step is numbered ({@code
 * seq}) and says whether its boundaries are at rest ({@code atRest}, from the runtime's {@code
 * DeployedPrograms.atRest}); once an event or an invocation arrives for the agent after such a
 * message, the mission says so ({@code attend}, numbered after it). A boundary then comes to the
 * mission again, as one does that meets the barrier of a synchronous block: a step boundary there,
 * or the end of an iteration that ran no instruction. The next request carries how many boundaries
 * were passed here, which the runtime counts as its own. The numbers order the pushes, taken on the
 * container's receiving thread, with the answers, taken later by the step's: an answer says nothing
 * of what arrived after it. A step that passes {@link #LONG_RUN} boundaries in a row no longer holds
 * its container's messages ({@link Outbox}), as it does while it runs between two requests of a wave.
 */
final class QuietBoundaries {

    /**
     * Boundaries passed in a row after which the step no longer counts as about to send: a lock-step
     * step passes one or two between its barriers; a loop that runs alone, thousands.
     */
    static final int LONG_RUN = 16;

    /** The number of the mission's latest {@code attend}: written by the receiving thread only. */
    private volatile long attendFrom;

    // Confined to the thread running the agent's step.
    private boolean atRest;
    private long toldAt;
    /** The place of the program's latest step, as the runtime's {@code IdleIterations} keeps it. */
    private int latestStep;
    private boolean barrierDue;
    private long passed;
    private int inARow;
    private boolean letGo;

    /** The mission's {@code attend} numbered {@code seq}: an event or invocation waits for a boundary. */
    void attend(long seq) {
        if (seq > attendFrom) {
            attendFrom = seq;
        }
    }

    /** What the mission's message {@code message} to the step (a resumption, an answer) says of its boundaries. */
    void told(JsonNode message) {
        JsonNode rest = message.get("atRest");
        atRest = rest != null;
        inARow = 0;
        if (atRest) {
            toldAt = message.get("seq").longValue();
            latestStep = rest.get("latest").intValue();
            barrierDue = rest.get("barrier").booleanValue();
        }
    }

    /**
     * Whether the loop head at case {@code head} is passed here: nothing arrived, and the iteration
     * ending here ran an instruction ({@code latestStep > head}) or meets no barrier.
     */
    boolean passLoopHead(int head) {
        if (!quiet() || latestStep <= head && barrierDue) {
            return false;
        }
        latestStep = head;
        return counted();
    }

    /**
     * Whether the step boundary after an instruction, {@code next} the case after it, is passed here:
     * nothing arrived, it meets no barrier, and {@code written} is false (what the step wrote to the
     * journal goes to the mission at the boundary, as it would be there at once in-process).
     */
    boolean passStep(int next, boolean written) {
        if (!quiet() || barrierDue || written) {
            return false;
        }
        latestStep = next;
        return counted();
    }

    /** Whether the end of an e-sequence, which meets no barrier, is passed here: nothing arrived. */
    boolean passEndOfSequence() {
        if (!quiet()) {
            return false;
        }
        return counted();
    }

    private boolean counted() {
        passed++;
        inARow++;
        return true;
    }

    /**
     * Whether the step has just passed {@link #LONG_RUN} boundaries in a row: it lets its container's
     * messages go from now on, until its next message ({@link #busyChangeOfNext}).
     */
    boolean lettingGo() {
        if (letGo || inARow < LONG_RUN) {
            return false;
        }
        letGo = true;
        return true;
    }

    /**
     * What the step's next message changes in its container's count of busy steps: -1, as any, or 0
     * for a step that let the container's messages go already.
     */
    int busyChangeOfNext() {
        int change = letGo ? 0 : -1;
        letGo = false;
        return change;
    }

    private boolean quiet() {
        return atRest && attendFrom <= toldAt;
    }

    /** The boundaries passed since the last request, which goes now: the next are the mission's until it answers. */
    long requested() {
        long passedHere = passed;
        passed = 0;
        atRest = false;
        inARow = 0;
        return passedHere;
    }

    /** The place of the program's latest step, which a request says with the boundaries it passed here. */
    int latestStep() {
        return latestStep;
    }
}
