package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import masl.runtime.AgentImplementation;
import masl.runtime.Label;

/**
 * The values of shared variables as they travel between a mission and its containers: JSON tagged
 * with their Java type ({@code {"int":3}}, {@code {"string":"a"}}, {@code {"agent":2}} for an agent by
 * proxy id), so that each side makes the same boxed type again; a label ({@code SLabel}'s value) as
 * its key ({@code {"label":"2.1"}}), which each side makes its own label of (the mission's, or the
 * container's view of it); an array of numbers, booleans, chars, strings or agents, of any dimensions, as
 * {@link ArrayValues} tags it ({@code {"string[]":["a",null]}}). A {@code double} or {@code float} that
 * JSON has no number for ({@code NaN}, the infinities) travels as the string Java reads it back from. A
 * value of any other type (a future) does not travel: {@link IllegalArgumentException}.
 */
final class Values {

    /** The labels of one side by key: the mission's ({@link MissionLabels}), a container's views ({@link RemoteLabel}). */
    interface Labels {
        Label label(String key);

        String key(Label label);
    }

    /** Where no label may travel: the arguments, results and attributes of primitives, which are never labels. */
    static final Labels NONE = new Labels() {
        @Override
        public Label label(String key) {
            throw new IllegalArgumentException("a label (" + key + ") is not a primitive's or an attribute's value");
        }

        @Override
        public String key(Label label) {
            throw new IllegalArgumentException("a label is not a primitive's or an attribute's value");
        }
    };

    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    private Values() {
    }

    /** {@code value}, which is no label, as it travels. */
    static JsonNode toJson(Object value) {
        return toJson(value, NONE);
    }

    static JsonNode toJson(Object value, Labels labels) {
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
            tagged.set("double", decimal(d));
        } else if (value instanceof Float f) {
            tagged.set("float", decimal(f));
        } else if (value instanceof Boolean b) {
            tagged.put("boolean", b);
        } else if (value instanceof Character c) {
            tagged.put("char", String.valueOf(c));
        } else if (value instanceof String s) {
            tagged.put("string", s);
        } else if (value instanceof AgentImplementation agent) {
            tagged.put("agent", AgentImplementation.proxyIdOf(agent));
        } else if (value instanceof Label label) {
            tagged.put("label", labels.key(label));
        } else if (value.getClass().isArray()) {
            return ArrayValues.toJson(value);
        } else {
            throw new IllegalArgumentException("a " + value.getClass().getSimpleName()
                    + " value cannot travel to a deployed agent");
        }
        return tagged;
    }

    /** The value {@code json} stands for, which is no label; agents are this side's implementations, by proxy id. */
    static Object fromJson(JsonNode json, List<? extends AgentImplementation> agents) {
        return fromJson(json, agents, NONE);
    }

    /** The value {@code json} stands for; agents are this side's implementations, by proxy id, labels its {@code labels}. */
    static Object fromJson(JsonNode json, List<? extends AgentImplementation> agents, Labels labels) {
        return fromJson(json, agents, labels, null);
    }

    /**
     * The value {@code json} stands for, as {@link #fromJson(JsonNode, List, Labels)}; {@code type}, if
     * not null, the type the receiver expects (a shared variable's), which an array of agents takes.
     */
    static Object fromJson(JsonNode json, List<? extends AgentImplementation> agents, Labels labels, Class<?> type) {
        String tag = json.fieldNames().hasNext() ? json.fieldNames().next() : "";
        JsonNode value = json.get(tag);
        if (ArrayValues.isArrayTag(tag)) {
            return ArrayValues.fromJson(tag, value, agents, type);
        }
        return switch (tag) {
            case "null" -> null;
            case "int" -> value.intValue();
            case "long" -> value.longValue();
            case "short" -> (short) value.intValue();
            case "byte" -> (byte) value.intValue();
            case "double" -> decimal(value);
            case "float" -> (float) decimal(value);
            case "boolean" -> value.booleanValue();
            case "char" -> value.textValue().charAt(0);
            case "string" -> value.textValue();
            case "agent" -> agents.get(value.intValue());
            case "label" -> labels.label(value.textValue());
            default -> throw new IllegalArgumentException("not a value: " + json);
        };
    }

    /**
     * A {@code double} or {@code float} as it travels, alone or in an array: a number, or the string
     * of one JSON has no number for ({@code NaN}, the infinities), which {@link #decimal(JsonNode)}
     * reads back.
     */
    static JsonNode decimal(Number value) {
        if (!Double.isFinite(value.doubleValue())) {
            return JSON.textNode(value.toString());
        }
        return value instanceof Float f ? JSON.numberNode(f) : JSON.numberNode(value.doubleValue());
    }

    /** A {@code double} as it travels: a number, or the string of one JSON has no number for. */
    static double decimal(JsonNode value) {
        return value.isTextual() ? Double.parseDouble(value.textValue()) : value.doubleValue();
    }
}
