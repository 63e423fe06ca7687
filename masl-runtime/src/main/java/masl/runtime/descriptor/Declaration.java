package masl.runtime.descriptor;

import java.util.List;
import java.util.Map;

/**
 * What one descriptor file declares, before its supertype is known.
 *
 * @param superFullClassName as written, or null
 * @param agent              the {@code <Agent>} element, where type-level problems are reported
 * @param fipa               the {@code <Fipa>} binding, or null for a type implemented in Java
 */
record Declaration(String shortName, String fullClassName, String superFullClassName, XmlElement agent,
        List<UtilityClass> utilityClasses, List<Primitive> primitives, List<Attribute> attributes,
        List<StateDeclaration> states, FipaBinding fipa) {

    int line() {
        return agent.line();
    }

    /** The member element at a position (a {@link Primitive} or {@link Attribute} keeps its element's). */
    XmlElement memberElementAt(int line, int column) {
        return agent.children().stream().filter(child -> child.line() == line && child.column() == column)
                .findFirst().orElse(agent);
    }

    /** A {@code <Class>}. */
    record UtilityClass(String name, XmlElement element) {
    }

    /**
     * A {@code <Permeability>}.
     *
     * @param members        rights (parsed from octal) by member id, in order; empty means "every member,
     *                       all rights" unless {@code unlistedRights} says otherwise
     * @param unlistedRights the rights of the members not listed ({@code unlisted_rights}), or null if not given
     */
    record StateDeclaration(String name, int umask, Map<String, Integer> members, List<XmlElement> memberElements,
            Integer unlistedRights, XmlElement element) {
    }
}
