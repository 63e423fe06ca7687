package masl.runtime.descriptor;

import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Rephrases the schema validator's (Xerces') messages, such as {@code cvc-complex-type.3.2.2: Attribute
 * 'x' is not allowed to appear in element 'Agent'.}, into what a descriptor author understands.
 * Messages it does not know keep their text without the {@code cvc-} code.
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

    private record Rule(Pattern pattern, Function<Matcher, String> rephrase) {
    }

    private static final List<Rule> RULES = List.of(
            rule("cvc-complex-type\\.3\\.2\\.2: Attribute '(.*)' is not allowed to appear in element '(.*)'\\.",
                    m -> "<" + m.group(2) + ">: unknown attribute '" + m.group(1) + "'"),
            rule("cvc-complex-type\\.4: Attribute '(.*)' must appear on element '(.*)'\\.",
                    m -> "<" + m.group(2) + ">: missing attribute '" + m.group(1) + "'"),
            rule("cvc-complex-type\\.2\\.4\\.[ac]: Invalid content was found starting with element '(.*)'\\."
                            + " One of '\\{(.*)\\}' is expected\\.",
                    m -> "unknown or misplaced element <" + m.group(1) + ">: expected " + elementList(m.group(2))),
            rule("cvc-complex-type\\.2\\.4\\.d: Invalid content was found starting with element '(.*)'\\..*",
                    m -> "unknown or misplaced element <" + m.group(1) + ">: no child element is allowed here"),
            rule("cvc-complex-type\\.2\\.4\\.b: The content of element '(.*)' is not complete\\."
                            + " One of '\\{(.*)\\}' is expected\\.",
                    m -> "<" + m.group(1) + "> is incomplete: expected " + elementList(m.group(2))),
            rule("cvc-complex-type\\.2\\.1: Element '(.*)' must have no character or element information item.*",
                    m -> "<" + m.group(1) + "> must be empty"),
            rule("cvc-complex-type\\.2\\.3: Element '(.*)' cannot have character \\[children\\].*",
                    m -> "<" + m.group(1) + ">: text is not allowed here, only elements"),
            rule("cvc-elt\\.1\\.a: Cannot find the declaration of element '(.*)'\\.",
                    m -> "the root element must be <Agent>, not <" + m.group(1) + ">"),
            rule("cvc-attribute\\.3: The value '(.*)' of attribute '(.*)' on element '(.*)' is not valid"
                            + " with respect to its type, '(.*)'\\.",
                    m -> "<" + m.group(3) + ">: invalid value '" + m.group(1) + "' for attribute '" + m.group(2)
                            + "': expected " + EXPECTED_VALUES.getOrDefault(m.group(4), "a value of type " + m.group(4))));

    /** Value-level errors that Xerces always follows with a clearer cvc-attribute.3 about the same attribute. */
    private static final Pattern FACET_ERROR =
            Pattern.compile("cvc-(pattern-valid|enumeration-valid|datatype-valid\\.1\\.2\\.[13]|minLength-valid):.*",
                    Pattern.DOTALL);

    private static final Pattern CODE_PREFIX = Pattern.compile("^cvc-[\\w.-]+: ");

    private SchemaMessages() {
    }

    /** True for messages that only announce the following cvc-attribute.3 and are dropped. */
    static boolean isFacetError(String validatorMessage) {
        return FACET_ERROR.matcher(validatorMessage).matches();
    }

    static String rephrase(String validatorMessage) {
        for (Rule rule : RULES) {
            Matcher matcher = rule.pattern.matcher(validatorMessage);
            if (matcher.matches()) {
                return rule.rephrase.apply(matcher);
            }
        }
        return CODE_PREFIX.matcher(validatorMessage).replaceFirst("");
    }

    private static Rule rule(String regex, Function<Matcher, String> rephrase) {
        return new Rule(Pattern.compile(regex, Pattern.DOTALL), rephrase);
    }

    /** {@code Class, Attribute} (the braces' content, possibly with quoted namespaces) as {@code <Class>, <Attribute>}. */
    private static String elementList(String names) {
        StringBuilder list = new StringBuilder();
        for (String name : names.split(",")) {
            String bare = name.trim().replaceAll("^\"[^\"]*\":", "");
            list.append(list.length() == 0 ? "" : ", ").append('<').append(bare).append('>');
        }
        return list.toString();
    }
}
