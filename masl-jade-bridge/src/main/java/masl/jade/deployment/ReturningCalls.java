package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.Set;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * A deployed program's calls that return from its step at once, holding no thread of its container
 * while the mission decides: those of {@link StandIn#SUSPENDING} after which the program, re-entered
 * at its resumption point, goes on where it would have gone on had the call answered true. The
 * generated code sets that point before such a call ({@code pc = next; if (!ctx.stepBoundary())
 * return;}) or goes back to it after ({@code continue;}). Such a call answers false, its request goes
 * once the step has returned, and the mission's answer, true or the step's resumption, starts the
 * program's next step at the answer's point. Not {@code endReaction}, whose case calls it again when
 * re-entered. A call that waits for its answer may be answered with the step's resumption too (an
 * {@code endReaction}): it answers false then, and the step goes on at the answer's point.
 */
final class ReturningCalls {

    private static final Set<String> RETURNING = Set.of("stepBoundary", "loopIteration", "busyWaitIteration",
            "endOfChild", "endOfSequence", "leave", "resumeInterrupted", "sleep", "await", "waitFor");

    // Confined to the thread running the agent's step.
    /** The request of the call the program returned from at once. */
    private Batch.Held returnedFrom;
    /** Whether the latest answer to a call resumed the step that waited in it. */
    private boolean resumedInCall;
    /** Whether the mission's next answer to the agent starts its program's next step. */
    private final AtomicBoolean awaitsResumption = new AtomicBoolean();

    /** Whether the program returns from its step at once when it calls {@code op}. */
    static boolean returns(String op) {
        return RETURNING.contains(op);
    }

    /** The program returns from its call {@code request}, which goes once its step has returned: false. */
    boolean returned(Batch.Held request) {
        returnedFrom = request;
        return false;
    }

    /** The mission's {@code answer} to a call the step waited in. */
    void answered(JsonNode answer) {
        resumedInCall = answer.path("resumed").booleanValue();
    }

    /**
     * Whether the last call the step waited in suspended it and the mission has resumed it since: the
     * call answered false (the program returns), and the step goes on from the program's resumption point.
     */
    boolean resumedInCall() {
        boolean resumed = resumedInCall;
        resumedInCall = false;
        return resumed;
    }

    /**
     * The request of the call the program returned from, or null; if there is one, the mission's next
     * answer to this agent starts its next step ({@link #resumption}).
     */
    Batch.Held taken() {
        Batch.Held request = returnedFrom;
        returnedFrom = null;
        if (request != null) {
            awaitsResumption.set(true);
        }
        return request;
    }

    /** Whether {@code message}, on the receiving thread, is the answer that starts the program's next step. */
    boolean resumption(JsonNode message) {
        return "answer".equals(message.path("kind").asText()) && awaitsResumption.compareAndSet(true, false);
    }
}
