package masl.runtime.descriptor;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * One element of a descriptor as read, with its position: the small tree the checks work on.
 * Text content is not kept (the schema allows none).
 *
 * @param attributes in document order
 * @param line       1-based line of the element's {@code <}
 * @param column     1-based column of the element's {@code <}
 */
record XmlElement(String name, Map<String, String> attributes, List<XmlElement> children, int line, int column) {

    /** The attributes that identify an element in messages, the first present one wins. */
    private static final List<String> IDENTIFYING_ATTRIBUTES = List.of(
            "function_name", "attribute_name", "permeability_name", "member_id", "parameter_name",
            "exception_name", "modifier_name", "name", "full_class_name");

    XmlElement {
        attributes = Collections.unmodifiableMap(new LinkedHashMap<>(attributes));
        children = List.copyOf(children);
    }

    /** The attribute's value, or null when absent. */
    String attribute(String attributeName) {
        return attributes.get(attributeName);
    }

    List<XmlElement> children(String elementName) {
        return children.stream().filter(child -> child.name.equals(elementName)).toList();
    }

    /** How messages name this element, e.g. {@code <Primitive function_name="stopGripper">}. */
    String describe() {
        for (String attributeName : IDENTIFYING_ATTRIBUTES) {
            String value = attributes.get(attributeName);
            if (value != null) {
                return "<" + name + " " + attributeName + "=\"" + value + "\">";
            }
        }
        return "<" + name + ">";
    }
}
