package masl.jade.deployment;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A container's programs' requests to the mission: what each says ({@link #written}), and the fields
 * of those of calls a program returns from with no argument ({@link ReturningCalls}: a step boundary,
 * a loop's iteration), but the agent that makes each: every program whose request says the same
 * shares one object, never changed once made, so that the arrivals of a container's agents at a
 * barrier are one run of a batch, found with no field compared ({@link Batch}), and a wave makes no
 * object of fields per agent. Requests after a long run of boundaries passed in the container
 * ({@link QuietBoundaries#LONG_RUN} or more) each have their own, so that their counts do not fill
 * this.
 */
final class Requests {

    /** What the fields say: the call, where the program made it, and the boundaries it passed since its last request. */
    private record Key(String op, int pc, long passed, int latest) {
    }

    private final Map<Key, ObjectNode> made = new ConcurrentHashMap<>();

    /**
     * The fields of request {@code op} made at case {@code pc}, with no argument, after the
     * boundaries {@code quiet} passed in the container, which the mission's answer counts from then
     * on ({@link QuietBoundaries#requested}). Not to be changed.
     */
    ObjectNode of(String op, int pc, QuietBoundaries quiet) {
        int latest = quiet.latestStep();
        long passed = quiet.requested();
        Key key = new Key(op, pc, passed, passed > 0 ? latest : 0);
        if (passed >= QuietBoundaries.LONG_RUN) {
            return fields(key);
        }
        ObjectNode fields = made.get(key);
        return fields != null ? fields : made.computeIfAbsent(key, Requests::fields);
    }

    /**
     * {@code request}, holding the call's arguments, with what every request says: the call
     * {@code op}, the case {@code pc} it was made at, and the boundaries {@code quiet} passed in the
     * container since the last request, as {@link #of} counts them.
     */
    static ObjectNode written(ObjectNode request, String op, int pc, QuietBoundaries quiet) {
        int latest = quiet.latestStep();
        return written(request, op, pc, quiet.requested(), latest);
    }

    private static ObjectNode fields(Key key) {
        return written(JsonNodeFactory.instance.objectNode(), key.op(), key.pc(), key.passed(), key.latest());
    }

    private static ObjectNode written(ObjectNode request, String op, int pc, long passed, int latest) {
        request.put("kind", "call").put("op", op).put("pc", pc);
        if (passed > 0) {
            request.put("passed", passed).put("latest", latest);
        }
        return request;
    }
}
