package masl.jade.deployment;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The fields of the requests a container's programs make of calls they return from with no argument
 * ({@link ReturningCalls}: a step boundary, a loop's iteration), but the agent that makes each: every
 * program whose request says the same shares one object, never changed once made, so that the arrivals
 * of a container's agents at a barrier are one run of a batch, found with no field compared
 * ({@link Batch}), and a wave makes no object of fields per agent. Requests after a long run of
 * boundaries passed in the container ({@link QuietBoundaries#LONG_RUN} or more) each have their own,
 * so that their counts do not fill this.
 */
final class ReturnRequests {

    /** What the fields say: the call, where the program made it, and the boundaries it passed since its last request. */
    private record Key(String op, int pc, long passed, int latest) {
    }

    private final Map<Key, ObjectNode> made = new ConcurrentHashMap<>();

    /**
     * The fields of request {@code op} made at case {@code pc}, after {@code passed} boundaries passed
     * in the container, the latest step then at {@code latest} (ignored if none was passed). Not to be changed.
     */
    ObjectNode of(String op, int pc, long passed, int latest) {
        Key key = new Key(op, pc, passed, passed > 0 ? latest : 0);
        if (passed >= QuietBoundaries.LONG_RUN) {
            return fields(key);
        }
        ObjectNode fields = made.get(key);
        return fields != null ? fields : made.computeIfAbsent(key, ReturnRequests::fields);
    }

    private static ObjectNode fields(Key key) {
        ObjectNode fields = JsonNodeFactory.instance.objectNode().put("kind", "call").put("op", key.op()).put("pc", key.pc());
        if (key.passed() > 0) {
            fields.put("passed", key.passed()).put("latest", key.latest());
        }
        return fields;
    }
}
