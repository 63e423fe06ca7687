package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import masl.runtime.AgentImplementation;

/**
 * The values of shared variables as they travel between a mission and its containers: JSON tagged
 * with their Java type ({@code {"int":3}}, {@code {"string":"a"}}, {@code {"agent":2}} for an agent by
 * proxy id), so that each side makes the same boxed type again. A value of any other type (a label,
 * a future) does not travel: {@link IllegalArgumentException}.
 */
final class Values {

    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    private Values() {
    }

    static JsonNode toJson(Object value) {
        ObjectNode tagged = JSON.objectNode();
        if (value == null) {
            return tagged.putNull("null");
        } else if (value instanceof Integer i) {
            tagged.put("int", i);
        } else if (value instanceof Long l) {
            tagged.put("long", l);
        } else if (value instanceof Short s) {
            tagged.put("short", s);
        } else if (value instanceof Byte b) {
            tagged.put("byte", b);
        } else if (value instanceof Double d) {
            tagged.put("double", d);
        } else if (value instanceof Float f) {
            tagged.put("float", f);
        } else if (value instanceof Boolean b) {
            tagged.put("boolean", b);
        } else if (value instanceof Character c) {
            tagged.put("char", String.valueOf(c));
        } else if (value instanceof String s) {
            tagged.put("string", s);
        } else if (value instanceof AgentImplementation agent) {
            tagged.put("agent", AgentImplementation.proxyIdOf(agent));
        } else {
            throw new IllegalArgumentException("a " + value.getClass().getSimpleName()
                    + " value cannot travel to a deployed agent");
        }
        return tagged;
    }

    /** The value {@code json} stands for; agents are this side's implementations, by proxy id. */
    static Object fromJson(JsonNode json, List<? extends AgentImplementation> agents) {
        String tag = json.fieldNames().hasNext() ? json.fieldNames().next() : "";
        JsonNode value = json.get(tag);
        return switch (tag) {
            case "null" -> null;
            case "int" -> value.intValue();
            case "long" -> value.longValue();
            case "short" -> (short) value.intValue();
            case "byte" -> (byte) value.intValue();
            case "double" -> value.doubleValue();
            case "float" -> value.floatValue();
            case "boolean" -> value.booleanValue();
            case "char" -> value.textValue().charAt(0);
            case "string" -> value.textValue();
            case "agent" -> agents.get(value.intValue());
            default -> throw new IllegalArgumentException("not a value: " + json);
        };
    }
}
