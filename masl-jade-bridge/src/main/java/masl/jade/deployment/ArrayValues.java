package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.reflect.Array;
import java.util.List;
import java.util.Map;
import masl.runtime.AgentImplementation;

/**
 * Arrays as they travel ({@link Values}): tagged with their MASL type, never with a Java class, as
 * {@code {"string[]":["a",null]}}, {@code {"int[][]":[[1,2],null]}}, {@code {"agent[]":[0,2]}} (agents
 * by proxy id); the items are plain JSON, a {@code char} a one-letter string, a {@code double} or
 * {@code float} that JSON has no number for ({@code NaN}, the infinities) a string Java reads back.
 * Each side makes an array of the element type the tag names; an array of agents is of the agent
 * type the receiver expects (a shared variable's declared type), of any agent where it expects none.
 * Arrays of other elements (objects, boxed numbers) do not travel.
 */
final class ArrayValues {

    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;
    /** The element types that travel, by the MASL name the tag gives them. */
    private static final Map<String, Class<?>> ELEMENTS = Map.of("int", int.class, "long", long.class,
            "short", short.class, "byte", byte.class, "double", double.class, "float", float.class,
            "boolean", boolean.class, "char", char.class, "string", String.class, "agent", AgentImplementation.class);

    private ArrayValues() {
    }

    /** Whether {@code tag} is an array's. */
    static boolean isArrayTag(String tag) {
        return tag.endsWith("[]");
    }

    /** {@code array} tagged with its MASL type; {@link IllegalArgumentException} for an array of other elements. */
    static ObjectNode toJson(Object array) {
        Class<?> element = array.getClass();
        StringBuilder dims = new StringBuilder();
        while (element.isArray()) {
            element = element.getComponentType();
            dims.append("[]");
        }
        String kind = kind(element);
        if (kind == null) {
            throw new IllegalArgumentException("a " + array.getClass().getSimpleName()
                    + " value cannot travel to a deployed agent: only arrays of numbers, booleans, chars,"
                    + " strings and agents do");
        }
        ObjectNode tagged = JSON.objectNode();
        tagged.set(kind + dims, items(array, dims.length() / 2 - 1));
        return tagged;
    }

    /**
     * The array tagged {@code tag} with {@code items}; agents are this side's, by proxy id; {@code type},
     * if not null, the array type the receiver expects, whose element type an array of agents takes.
     */
    static Object fromJson(String tag, JsonNode items, List<? extends AgentImplementation> agents, Class<?> type) {
        String kind = tag.substring(0, tag.indexOf('['));
        int depth = (tag.length() - kind.length()) / 2;
        Class<?> element = ELEMENTS.get(kind);
        if (element == null || !tag.substring(kind.length()).equals("[]".repeat(depth))) {
            throw new IllegalArgumentException("not a value: " + tag);
        }
        if (type != null) {
            Class<?> expected = type;
            for (int level = 0; level < depth && expected.isArray(); level++) {
                expected = expected.getComponentType();
            }
            boolean fits = expected == element || element == AgentImplementation.class
                    && AgentImplementation.class.isAssignableFrom(expected);
            if (!fits || arrayOf(expected, depth) != type) {
                throw new IllegalArgumentException("a " + tag + " value where a " + type.getSimpleName() + " is expected");
            }
            element = expected;
        }
        return array(items, element, depth, agents);
    }

    /** The class of arrays of {@code depth} dimensions of {@code element}. */
    private static Class<?> arrayOf(Class<?> element, int depth) {
        return Array.newInstance(element, new int[depth]).getClass();
    }

    private static String kind(Class<?> element) {
        if (AgentImplementation.class.isAssignableFrom(element)) {
            return "agent";
        }
        for (Map.Entry<String, Class<?>> known : ELEMENTS.entrySet()) {
            if (known.getValue() == element) {
                return known.getKey();
            }
        }
        return null;
    }

    private static JsonNode items(Object array, int innerDepth) {
        ArrayNode items = JSON.arrayNode();
        for (int i = 0, n = Array.getLength(array); i < n; i++) {
            Object item = Array.get(array, i);
            if (item == null) {
                items.addNull();
            } else if (innerDepth > 0) {
                items.add(items(item, innerDepth - 1));
            } else {
                items.add(item(item));
            }
        }
        return items;
    }

    private static JsonNode item(Object item) {
        if (item instanceof Double || item instanceof Float) {
            return Values.decimal((Number) item);
        } else if (item instanceof Number number) {
            return JSON.numberNode(number.longValue());
        } else if (item instanceof Boolean b) {
            return JSON.booleanNode(b);
        } else if (item instanceof AgentImplementation agent) {
            return JSON.numberNode(AgentImplementation.proxyIdOf(agent));
        }
        return JSON.textNode(item.toString());
    }

    private static Object array(JsonNode items, Class<?> element, int depth, List<? extends AgentImplementation> agents) {
        if (!items.isArray()) {
            throw new IllegalArgumentException("not an array's items: " + items);
        }
        Object array = Array.newInstance(depth > 1 ? arrayOf(element, depth - 1) : element, items.size());
        for (int i = 0; i < items.size(); i++) {
            JsonNode item = items.get(i);
            if (!item.isNull()) {
                Array.set(array, i, depth > 1 ? array(item, element, depth - 1, agents) : item(item, element, agents));
            }
        }
        return array;
    }

    private static Object item(JsonNode item, Class<?> element, List<? extends AgentImplementation> agents) {
        if (element == int.class) {
            return item.intValue();
        } else if (element == long.class) {
            return item.longValue();
        } else if (element == short.class) {
            return (short) item.intValue();
        } else if (element == byte.class) {
            return (byte) item.intValue();
        } else if (element == double.class) {
            return Values.decimal(item);
        } else if (element == float.class) {
            return (float) Values.decimal(item);
        } else if (element == boolean.class) {
            return item.booleanValue();
        } else if (element == char.class) {
            return item.textValue().charAt(0);
        } else if (element == String.class) {
            return item.textValue();
        }
        return agents.get(item.intValue());
    }
}
