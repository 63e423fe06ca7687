package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A deployed agent's loop heads passed in its container, with no message, while the mission says
 * nothing waits for them there: every message the mission sends to the agent's step is numbered
 * ({@code seq}) and says whether its loop heads are at rest ({@code loopHeads}, from the runtime's
 * {@code DeployedPrograms.loopHeadsAtRest}), and once an event or an invocation arrives for the agent
 * after such a message, the mission says so ({@code attend}, numbered after it). A loop head then
 * comes to the mission again, as one does that ends an iteration which ran no instruction in a
 * synchronous block (it meets the barrier). The next request carries the loop heads passed here, which
 * the runtime counts as its own. The numbers order the pushes, taken on the container's receiving
 * thread, with the answers, taken later by the step's: an answer says nothing of what arrived after it.
 */
final class LoopHeads {

    /** The number of the mission's latest {@code attend}: written by the receiving thread only. */
    private volatile long attendFrom;

    // Confined to the thread running the agent's step.
    private boolean atRest;
    private long toldAt;
    /** The place of the program's latest step, as the runtime's {@code IdleIterations} keeps it. */
    private int latestStep;
    private boolean barrierDue;
    private long passed;

    /** The mission's {@code attend} numbered {@code seq}: an event or invocation waits for a boundary. */
    void attend(long seq) {
        if (seq > attendFrom) {
            attendFrom = seq;
        }
    }

    /** What the mission's message {@code message} to the step (a resumption, an answer) says of its loop heads. */
    void told(JsonNode message) {
        JsonNode heads = message.get("loopHeads");
        atRest = heads != null;
        if (atRest) {
            toldAt = message.get("seq").longValue();
            latestStep = heads.get("latest").intValue();
            barrierDue = heads.get("barrier").booleanValue();
        }
    }

    /**
     * Whether the loop head at case {@code head} is passed here: nothing arrived since the mission said
     * the heads are at rest, and the iteration ending here ran an instruction or is in no synchronous
     * block ({@code latestStep <= head}: it ran none).
     */
    boolean pass(int head) {
        if (!atRest || attendFrom > toldAt || latestStep <= head && barrierDue) {
            return false;
        }
        latestStep = head;
        passed++;
        return true;
    }

    /** Adds to {@code request} the loop heads passed since the last request; the next are the mission's until it answers. */
    void request(ObjectNode request) {
        if (passed > 0) {
            request.put("passed", passed).put("latest", latestStep);
            passed = 0;
        }
        atRest = false;
    }
}
