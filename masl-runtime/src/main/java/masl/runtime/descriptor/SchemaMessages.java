package masl.runtime.descriptor;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Rephrases the schema validator's (Xerces') messages, such as {@code cvc-complex-type.3.2.2: Attribute
 * 'x' is not allowed to appear in element 'Agent'.}, into what a descriptor author understands.
 *
 * <p>Xerces words its messages in the JVM's default language and ignores a request for another, so
 * they are recognised by their error code, which is never translated, and by their quoted arguments;
 * which argument is which is settled with the attributes of the element being validated, not by the
 * wording. Messages without a known code keep their text, without the code.
 */
final class SchemaMessages {

    /** What each simple type of agent-type.xsd accepts, for "invalid value" messages. */
    private static final Map<String, String> EXPECTED_VALUES = Map.of(
            "octalRights", "3 octal digits (u g o, like 644)",
            "boolean", "true or false",
            "modifierName", "public, static or final",
            "targetLanguage", "java",
            "name", "a Java identifier",
            "memberId", "an identifier without spaces",
            "javaClassName", "a fully qualified Java class name",
            "javaTypeName", "a Java type (void, int.class, java.lang.String, int[], a class name)");

    /** Some languages put a space before the colon. */
    private static final Pattern CODE = Pattern.compile("^(cvc-[\\w.-]+)\\s*:\\s*(.*)$", Pattern.DOTALL);
    /**
     * A quoted name, or a quoted list of names in braces; without spaces, so that the apostrophes of
     * words such as French "l'attribut" are not taken for quotes.
     */
    private static final Pattern QUOTED = Pattern.compile("'(\\{[^}]*\\}|[^'\\s]+)'");

    /**
     * Value-level errors that Xerces always follows with a cvc-attribute.3 naming the attribute; the
     * schema has no element with text content, so every one of them concerns an attribute.
     */
    private static final Pattern FACET_CODE =
            Pattern.compile("cvc-(pattern-valid|enumeration-valid|datatype-valid\\.1\\.2\\.[13]|minLength-valid)");

    private SchemaMessages() {
    }

    /** True for messages that only announce the following cvc-attribute.3, and are to be dropped. */
    static boolean isFacetError(String validatorMessage) {
        Matcher code = CODE.matcher(validatorMessage);
        return code.matches() && FACET_CODE.matcher(code.group(1)).matches();
    }

    /**
     * @param element    the element being validated when the error came
     * @param attributes that element's attributes, to tell attribute names from other arguments
     */
    static String rephrase(String validatorMessage, String element, Map<String, String> attributes) {
        Matcher code = CODE.matcher(validatorMessage);
        if (!code.matches()) {
            return validatorMessage;
        }
        List<String> quoted = quoted(code.group(2));
        String rephrased = switch (code.group(1)) {
            case "cvc-complex-type.3.2.2" -> other(quoted, element)
                    .map(attribute -> "<" + element + ">: unknown attribute '" + attribute + "'").orElse(null);
            case "cvc-complex-type.4" -> other(quoted, element)
                    .map(attribute -> "<" + element + ">: missing attribute '" + attribute + "'").orElse(null);
            case "cvc-complex-type.2.4.a", "cvc-complex-type.2.4.c" -> quoted.size() < 2 ? null
                    : "unknown or misplaced element <" + notAList(quoted) + ">: expected " + elementList(quoted);
            case "cvc-complex-type.2.4.d" -> quoted.isEmpty() ? null
                    : "unknown or misplaced element <" + quoted.get(0) + ">: no child element is allowed here";
            case "cvc-complex-type.2.4.b" -> quoted.size() < 2 ? null
                    : "<" + notAList(quoted) + "> is incomplete: expected " + elementList(quoted);
            case "cvc-complex-type.2.1" -> quoted.isEmpty() ? null : "<" + quoted.get(0) + "> must be empty";
            case "cvc-complex-type.2.3" -> quoted.isEmpty() ? null
                    : "<" + quoted.get(0) + ">: text is not allowed here, only elements";
            case "cvc-elt.1.a" -> quoted.isEmpty() ? null
                    : "the root element must be <Agent>, not <" + quoted.get(0) + ">";
            case "cvc-attribute.3" -> invalidValue(code.group(2), quoted, element, attributes);
            default -> null;
        };
        return rephrased != null ? rephrased : code.group(2);
    }

    /** The attribute whose value is invalid is the one of the element named among the arguments. */
    private static String invalidValue(String text, List<String> quoted, String element,
            Map<String, String> attributes) {
        for (Map.Entry<String, String> attribute : attributes.entrySet()) {
            if (quoted.contains(attribute.getKey()) && text.contains("'" + attribute.getValue() + "'")) {
                String type = quoted.stream().filter(EXPECTED_VALUES::containsKey)
                        .filter(name -> !name.equals(attribute.getKey()) && !name.equals(attribute.getValue()))
                        .findFirst().orElse(null);
                return "<" + element + ">: invalid value '" + attribute.getValue() + "' for attribute '"
                        + attribute.getKey() + "'" + (type == null ? "" : ": expected " + EXPECTED_VALUES.get(type));
            }
        }
        return null;
    }

    private static List<String> quoted(String text) {
        List<String> quoted = new ArrayList<>();
        Matcher matcher = QUOTED.matcher(text);
        while (matcher.find()) {
            quoted.add(matcher.group(1));
        }
        return quoted;
    }

    /** The first argument that is not {@code element}: the other name of a two-name message. */
    private static Optional<String> other(List<String> quoted, String element) {
        return quoted.stream().filter(name -> !name.equals(element)).findFirst();
    }

    private static String notAList(List<String> quoted) {
        return quoted.stream().filter(name -> !name.startsWith("{")).findFirst().orElse("?");
    }

    /** {@code {Class, Attribute}} (possibly with quoted namespaces) as {@code <Class>, <Attribute>}. */
    private static String elementList(List<String> quoted) {
        String names = quoted.stream().filter(name -> name.startsWith("{")).findFirst().orElse("{}");
        StringBuilder list = new StringBuilder();
        for (String name : names.substring(1, names.length() - 1).split(",")) {
            String bare = name.trim().replaceAll("^\"[^\"]*\":", "");
            list.append(list.length() == 0 ? "" : ", ").append('<').append(bare).append('>');
        }
        return list.toString();
    }
}
