package masl.jade.acl;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.reflect.Array;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Java values of primitives' parameters and results, to and from JSON. JSON has numbers, strings,
 * booleans, null, arrays and objects; the mapping is:
 * <ul>
 * <li>to JSON: {@code null}, booleans, numbers, strings, {@code char} (a one-character string),
 * arrays and collections (arrays), maps (objects, keys by {@code String.valueOf}); any other object
 * as the string {@code String.valueOf} gives, never by reading its properties;</li>
 * <li>from JSON, by the parameter's type: integral types from integral numbers in range,
 * {@code double}/{@code float} from any number, {@code boolean}, {@code char} from a one-character
 * string, {@code String} from any value but an array or object (a number or boolean by
 * {@code String.valueOf}, as MASL §3 converts where a {@code String} is expected), arrays element by
 * element, {@code Object} as the natural Java value ({@code Integer}, {@code Long}, {@code Double},
 * {@code String}, {@code Boolean}, {@code List}, {@code Map}). Other types cannot be given in JSON.</li>
 * </ul>
 */
public final class JsonValues {

    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private JsonValues() {
    }

    /** The JSON form of {@code value}. */
    public static JsonNode toJson(Object value) {
        if (value == null) {
            return NODES.nullNode();
        }
        if (value instanceof Boolean b) {
            return NODES.booleanNode(b);
        }
        if (value instanceof Integer || value instanceof Short || value instanceof Byte) {
            return NODES.numberNode(((Number) value).intValue());
        }
        if (value instanceof Long l) {
            return NODES.numberNode(l);
        }
        if (value instanceof Float || value instanceof Double) {
            return NODES.numberNode(((Number) value).doubleValue());
        }
        if (value instanceof BigInteger big) {
            return NODES.numberNode(big);
        }
        if (value instanceof BigDecimal big) {
            return NODES.numberNode(big);
        }
        if (value instanceof Iterable<?> iterable) {
            ArrayNode array = NODES.arrayNode();
            iterable.forEach(element -> array.add(toJson(element)));
            return array;
        }
        if (value.getClass().isArray()) {
            ArrayNode array = NODES.arrayNode();
            for (int i = 0; i < Array.getLength(value); i++) {
                array.add(toJson(Array.get(value, i)));
            }
            return array;
        }
        if (value instanceof Map<?, ?> map) {
            ObjectNode object = NODES.objectNode();
            map.forEach((key, element) -> object.set(String.valueOf(key), toJson(element)));
            return object;
        }
        return NODES.textNode(String.valueOf(value));
    }

    /**
     * The argument as a value of {@code type}.
     *
     * @param what names the parameter in messages, e.g. {@code argument 1 of log}
     * @throws ContentException at the argument's position if JSON cannot give that type
     */
    public static Object fromJson(Argument argument, Class<?> type, String what) throws ContentException {
        Object value = convert(argument.value(), type);
        if (value == NO_VALUE) {
            throw new ContentException(what + ": expected " + describe(type) + ", got " + shortText(argument.value()),
                    argument.line(), argument.column());
        }
        return value;
    }

    /** Marks a JSON value that has no form in the type asked for. */
    private static final Object NO_VALUE = new Object();

    private static Object convert(JsonNode node, Class<?> type) {
        if (node.isNull()) {
            return type.isPrimitive() ? NO_VALUE : null;
        }
        if (type == int.class || type == Integer.class) {
            return node.isIntegralNumber() && node.canConvertToInt() ? node.intValue() : NO_VALUE;
        }
        if (type == long.class || type == Long.class) {
            return node.isIntegralNumber() && node.canConvertToLong() ? node.longValue() : NO_VALUE;
        }
        if (type == short.class || type == Short.class) {
            return inRange(node, Short.MIN_VALUE, Short.MAX_VALUE) ? (Object) (short) node.intValue() : NO_VALUE;
        }
        if (type == byte.class || type == Byte.class) {
            return inRange(node, Byte.MIN_VALUE, Byte.MAX_VALUE) ? (Object) (byte) node.intValue() : NO_VALUE;
        }
        if (type == double.class || type == Double.class) {
            return node.isNumber() ? node.doubleValue() : NO_VALUE;
        }
        if (type == float.class || type == Float.class) {
            return node.isNumber() ? node.floatValue() : NO_VALUE;
        }
        if (type == boolean.class || type == Boolean.class) {
            return node.isBoolean() ? node.booleanValue() : NO_VALUE;
        }
        if (type == char.class || type == Character.class) {
            return node.isTextual() && node.textValue().length() == 1 ? node.textValue().charAt(0) : NO_VALUE;
        }
        if (type == String.class) {
            return node.isContainerNode() ? NO_VALUE : node.asText();
        }
        if (type.isArray()) {
            return node.isArray() ? array(node, type.getComponentType()) : NO_VALUE;
        }
        if (type == Object.class) {
            return natural(node);
        }
        return NO_VALUE;
    }

    private static boolean inRange(JsonNode node, int min, int max) {
        return node.isIntegralNumber() && node.canConvertToInt() && node.intValue() >= min && node.intValue() <= max;
    }

    private static Object array(JsonNode node, Class<?> componentType) {
        Object array = Array.newInstance(componentType, node.size());
        for (int i = 0; i < node.size(); i++) {
            Object element = convert(node.get(i), componentType);
            if (element == NO_VALUE) {
                return NO_VALUE;
            }
            Array.set(array, i, element);
        }
        return array;
    }

    private static Object natural(JsonNode node) {
        if (node.isArray()) {
            List<Object> list = new ArrayList<>();
            node.forEach(element -> list.add(natural(element)));
            return list;
        }
        if (node.isObject()) {
            Map<String, Object> map = new LinkedHashMap<>();
            node.fields().forEachRemaining(field -> map.put(field.getKey(), natural(field.getValue())));
            return map;
        }
        if (node.isIntegralNumber()) {
            return node.canConvertToInt() ? (Object) node.intValue()
                    : node.canConvertToLong() ? (Object) node.longValue() : node.bigIntegerValue();
        }
        if (node.isNumber()) {
            return node.doubleValue();
        }
        if (node.isBoolean()) {
            return node.booleanValue();
        }
        return node.isNull() ? null : node.asText();
    }

    private static String describe(Class<?> type) {
        if (type.isArray()) {
            return "an array of " + describe(type.getComponentType()).replaceFirst("^an? ", "") + " values";
        }
        String name = type == String.class ? "string (or number or boolean)"
                : type == char.class || type == Character.class ? "char (a one-character string)"
                : type == Object.class ? "value" : type.getSimpleName();
        return (name.matches("^[aeiouAEIOU].*") ? "an " : "a ") + name;
    }

    private static String shortText(JsonNode node) {
        String text = node.toString();
        return text.length() <= 40 ? text : text.substring(0, 37) + "...";
    }
}
