package masl.jade.deployment;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import masl.runtime.DeployedPrograms;

/**
 * The fields of the messages that let a deployed agent's step go on with nothing to give it: a step
 * that starts ({@code resume}), or a call its step returned from, answered with the step's resumption
 * (a barrier's trip, most often). Every stand-in whose message says the same shares one object, never
 * changed once made: a trip's wake-ups of a container's agents are then one run of a batch, found with
 * no field compared ({@link Batch}), and a wave makes no object of fields per agent.
 */
final class WakeUps {

    /** What the fields say: a resumption in a call or a step's start, where, and whether its boundaries are at rest. */
    private record Key(boolean resumed, int pc, DeployedPrograms.AtRest rest) {
    }

    private final Map<Key, ObjectNode> made = new ConcurrentHashMap<>();

    /**
     * The fields of a wake-up: the answer that resumes the call its step returned from if
     * {@code resumed}, else the start of a step; from {@code pc}, its boundaries at rest as
     * {@code rest} says (null: they come to the mission). Not to be changed.
     */
    ObjectNode of(boolean resumed, int pc, DeployedPrograms.AtRest rest) {
        Key key = new Key(resumed, pc, rest);
        ObjectNode fields = made.get(key);
        return fields != null ? fields : made.computeIfAbsent(key, WakeUps::fields);
    }

    private static ObjectNode fields(Key key) {
        ObjectNode fields = JsonNodeFactory.instance.objectNode();
        if (key.resumed()) {
            fields.put("kind", "answer").put("value", false).put("resumed", true);
        } else {
            fields.put("kind", "resume");
        }
        return withRest(fields.put("pc", key.pc()), key.rest());
    }

    /** {@code message}, which lets a step go on, saying that its boundaries are at rest as {@code rest} says (null: it says nothing). */
    static ObjectNode withRest(ObjectNode message, DeployedPrograms.AtRest rest) {
        if (rest != null) {
            message.putObject("atRest").put("latest", rest.latestStep()).put("barrier", rest.barrierDue());
        }
        return message;
    }
}
