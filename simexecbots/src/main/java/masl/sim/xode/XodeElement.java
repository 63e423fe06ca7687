package masl.sim.xode;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * A parsed XML element of an XODE file: name, attributes in document order, child elements and
 * where it starts. Text content is dropped because XODE carries everything in attributes.
 */
public final class XodeElement {

    private final String name;
    private final SourceLocation location;
    private final Map<String, String> attributes = new LinkedHashMap<>();
    private final List<XodeElement> children = new ArrayList<>();

    XodeElement(String name, SourceLocation location) {
        this.name = name;
        this.location = location;
    }

    public String name() {
        return name;
    }

    public SourceLocation location() {
        return location;
    }

    /** Attributes in document order; namespace-qualified ones (xsi:…) are not included. */
    public Map<String, String> attributes() {
        return Collections.unmodifiableMap(attributes);
    }

    public Optional<String> attribute(String attributeName) {
        return Optional.ofNullable(attributes.get(attributeName));
    }

    public List<XodeElement> children() {
        return Collections.unmodifiableList(children);
    }

    /** Children with the given name, in document order. */
    public List<XodeElement> children(String childName) {
        List<XodeElement> named = new ArrayList<>();
        for (XodeElement child : children) {
            if (child.name.equals(childName)) {
                named.add(child);
            }
        }
        return named;
    }

    /** The first child with the given name, if any. */
    public Optional<XodeElement> child(String childName) {
        return children.stream().filter(c -> c.name.equals(childName)).findFirst();
    }

    void putAttribute(String attributeName, String value) {
        attributes.put(attributeName, value);
    }

    void addChild(XodeElement child) {
        children.add(child);
    }
}
