package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The one message that a side's held coordination messages go as ({@link Outbox}), in the order they
 * were added: {@code {"kind":"batch","runs":[…]}}. Messages that follow one another and are alike but
 * for the agent they concern and their number make one run, {@code {"like":{the fields they
 * share},"agent":[…],"seq":[…]}}: in a lock-step trip, every wake-up of a container's agents is alike,
 * and so is every arrival, so that a wave of 500 agents says its fields once and two numbers per agent
 * rather than an object each, a twentieth of the text to write, sign, send and parse.
 *
 * <p>The messages {@link #each} gives back are objects of their own, but those of one run share
 * their common fields ({@link RunMember}): none is copied for each message.
 */
public final class Batch {

    /** The fields that may differ between the messages of a run, each a column of the run. */
    private static final List<String> COLUMNS = List.of("agent", "seq");

    private Batch() {
    }

    /**
     * A message as an outbox holds it: its fields but its columns, and its columns, null where it has
     * none. Messages that say the same to several agents may share one {@code fields} object
     * ({@link WakeUps}), which is then never changed: a run of them is found by its identity, with no
     * field compared.
     */
    record Held(ObjectNode fields, JsonNode agent, JsonNode seq) {

        /** {@code message} as held: its columns are taken out of it, which is the outbox's from then on. */
        static Held of(ObjectNode message) {
            return new Held(message, message.remove("agent"), message.remove("seq"));
        }
    }

    /** The batch of {@code messages}, in their order; it shares their fields, which must not change while it is sent. */
    static ObjectNode of(List<Held> messages) {
        ObjectNode batch = JsonNodeFactory.instance.objectNode().put("kind", "batch");
        ArrayNode runs = batch.putArray("runs");
        Held like = null;
        ArrayNode agents = null;
        ArrayNode seqs = null;
        for (Held message : messages) {
            if (like == null || !alike(message, like)) {
                like = message;
                ObjectNode run = runs.addObject();
                run.set("like", message.fields());
                agents = message.agent() == null ? null : run.putArray("agent");
                seqs = message.seq() == null ? null : run.putArray("seq");
            }
            if (agents != null) {
                agents.add(message.agent());
            }
            if (seqs != null) {
                seqs.add(message.seq());
            }
        }
        return batch;
    }

    /**
     * Whether {@code message} joins the run whose first message is {@code like}: it has the same
     * columns, at least one, and the same other fields, the same object or in the same order with the
     * same values. The messages of a wave are made by the same code, their fields in one order:
     * walking both in step spares a lookup per field. Alike messages whose fields came in another
     * order make runs of their own, which carry them as well.
     */
    private static boolean alike(Held message, Held like) {
        if ((message.agent() == null) != (like.agent() == null) || (message.seq() == null) != (like.seq() == null)
                || message.agent() == null && message.seq() == null) {
            return false;
        }
        if (message.fields() == like.fields()) {
            return true;
        }
        if (message.fields().size() != like.fields().size()) {
            return false;
        }
        Iterator<Map.Entry<String, JsonNode>> first = like.fields().fields();
        for (Iterator<Map.Entry<String, JsonNode>> fields = message.fields().fields(); fields.hasNext(); ) {
            Map.Entry<String, JsonNode> field = fields.next();
            Map.Entry<String, JsonNode> same = first.next();
            if (!field.getKey().equals(same.getKey()) || !field.getValue().equals(same.getValue())) {
                return false;
            }
        }
        return true;
    }

    /**
     * The messages of a batch in their order, or {@code message} if it is not a batch. A run that is
     * not well made (a column that is no array, shared fields that are no object or hold a column)
     * gives one empty message, which names no agent: a side refuses it, or the batch.
     */
    public static List<ObjectNode> each(ObjectNode message) {
        List<ObjectNode> each = new ArrayList<>();
        if (!"batch".equals(message.path("kind").asText())) {
            each.add(message);
            return each;
        }
        for (JsonNode run : message.path("runs")) {
            int count = count(run);
            if (count < 0 || !(run.get("like") instanceof ObjectNode like) || COLUMNS.stream().anyMatch(like::has)) {
                each.add(JsonNodeFactory.instance.objectNode());
                continue;
            }
            Map<String, JsonNode> shared = new LinkedHashMap<>();
            like.fields().forEachRemaining(field -> shared.put(field.getKey(), field.getValue()));
            Map<String, JsonNode> fields = Collections.unmodifiableMap(shared);
            JsonNode agents = run.path("agent");
            JsonNode seqs = run.path("seq");
            for (int i = 0; i < count; i++) {
                each.add(new ObjectNode(JsonNodeFactory.instance, new RunMember(fields, agents.get(i), seqs.get(i))));
            }
        }
        return each;
    }

    /** How many messages {@code run} stands for: its longest column's, 1 if it has none; -1 if a column is no array. */
    private static int count(JsonNode run) {
        int count = -1;
        for (String column : COLUMNS) {
            JsonNode values = run.get(column);
            if (values != null) {
                if (!values.isArray()) {
                    return -1;
                }
                count = Math.max(count, values.size());
            }
        }
        return count < 0 ? 1 : count;
    }
}
