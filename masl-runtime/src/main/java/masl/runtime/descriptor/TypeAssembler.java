package masl.runtime.descriptor;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Puts a {@link Declaration} together with its resolved supertype into an {@link AgentType}, checking
 * the rules that involve inherited members: redefinitions (same kind, same member id), ids not taken by
 * an inherited member, {@code <Member>} ids, countermeasures. Builds the permeability states by the
 * inheritance rule of {@link AgentType#states()}.
 */
final class TypeAssembler {

    private final Declaration declaration;
    private final AgentType supertype;
    private final Problems problems;

    private TypeAssembler(Declaration declaration, AgentType supertype, Problems problems) {
        this.declaration = declaration;
        this.supertype = supertype;
        this.problems = problems;
    }

    /** The type; any rule broken is added to {@code problems} (the type is then not to be used). */
    static AgentType assemble(Declaration declaration, AgentType supertype, DescriptorSource source,
            Problems problems) {
        TypeAssembler assembler = new TypeAssembler(declaration, supertype, problems);
        assembler.checkAgainstInherited();
        List<PermeabilityState> states = assembler.states();
        AgentType type = new AgentType(declaration, source, supertype, states);
        assembler.checkCountermeasures(type);
        return type;
    }

    private void checkAgainstInherited() {
        if (supertype == null) {
            return;
        }
        Map<String, String> inheritedNameById = new HashMap<>();
        supertype.primitives().forEach(p -> inheritedNameById.put(p.memberId(), p.name()));
        supertype.attributes().forEach(a -> inheritedNameById.put(a.memberId(), a.name()));
        for (Primitive primitive : declaration.primitives()) {
            XmlElement element = declaration.memberElementAt(primitive.line(), primitive.column());
            if (supertype.findAttribute(primitive.name()).isPresent()) {
                problems.at(element, "primitive '" + primitive.name() + "' has the name of an attribute inherited from "
                        + declaringType(primitive.name()));
            } else {
                checkId(element, primitive.name(), primitive.memberId(),
                        supertype.findPrimitive(primitive.name()).map(Primitive::memberId).orElse(null),
                        inheritedNameById);
            }
        }
        for (Attribute attribute : declaration.attributes()) {
            XmlElement element = declaration.memberElementAt(attribute.line(), attribute.column());
            if (supertype.findPrimitive(attribute.name()).isPresent()) {
                problems.at(element, "attribute '" + attribute.name() + "' has the name of a primitive inherited from "
                        + declaringType(attribute.name()));
            } else {
                checkId(element, attribute.name(), attribute.memberId(),
                        supertype.findAttribute(attribute.name()).map(Attribute::memberId).orElse(null),
                        inheritedNameById);
            }
        }
    }

    /**
     * A redefinition ({@code redefinedId} not null) must keep the member id, so that the inherited
     * states' rights keep applying to it; a new member must not take an inherited member's id.
     */
    private void checkId(XmlElement element, String name, String id, String redefinedId,
            Map<String, String> inheritedNameById) {
        if (redefinedId != null && !redefinedId.equals(id)) {
            problems.at(element, "redefines '" + name + "' of " + declaringType(name) + " with member_id '" + id
                    + "': a redefinition keeps the inherited member_id '" + redefinedId + "'");
        } else if (redefinedId == null && inheritedNameById.containsKey(id)) {
            String owner = inheritedNameById.get(id);
            problems.at(element, "duplicate member_id '" + id + "': already used by '" + owner + "' inherited from "
                    + declaringType(owner));
        }
    }

    private void checkCountermeasures(AgentType type) {
        for (Primitive primitive : declaration.primitives()) {
            String countermeasure = primitive.countermeasure();
            if (countermeasure == null) {
                continue;
            }
            XmlElement element = declaration.memberElementAt(primitive.line(), primitive.column());
            if (primitive.synchronous()) {
                problems.at(element, "countermeasure '" + countermeasure
                        + "' on a synchronous primitive: only asynchronous primitives (synchronous_call=\"false\") have one");
            }
            if (countermeasure.equals(primitive.name())) {
                problems.at(element, "countermeasure '" + countermeasure + "' names the primitive itself");
            } else if (type.findPrimitive(countermeasure).isEmpty()) {
                problems.at(element, "countermeasure '" + countermeasure + "' names no primitive of "
                        + declaration.shortName());
            } else if (!type.findPrimitive(countermeasure).get().parameters().isEmpty()) {
                problems.at(element, "countermeasure '" + countermeasure
                        + "' takes parameters: the runtime invokes it without arguments");
            }
        }
    }

    /**
     * The states: the supertype's in its order, each replaced in place by this descriptor's
     * redeclaration, then this descriptor's new states. See the README, "Descriptors", for the rights.
     */
    private List<PermeabilityState> states() {
        Set<String> visibleIds = visibleMemberIds();
        Map<String, PermeabilityState> states = new LinkedHashMap<>();
        if (supertype != null) {
            for (PermeabilityState inherited : supertype.states()) {
                Map<String, Integer> granted = new HashMap<>();
                for (String id : visibleIds) {
                    granted.put(id, isInherited(id) ? inherited.granted(id) : inherited.grantedToUnlisted());
                }
                states.put(inherited.name(), new PermeabilityState(inherited.name(), inherited.umask(), granted,
                        inherited.grantedToUnlisted(), inherited.line()));
            }
        }
        for (Declaration.StateDeclaration declared : declaration.states()) {
            checkMembers(declared, visibleIds);
            PermeabilityState inherited = states.get(declared.name());
            Map<String, Integer> granted = new HashMap<>();
            int grantedToUnlisted;
            Integer unlisted = declared.unlistedRights();
            if (declared.members().isEmpty()) {
                int rights = unlisted != null ? unlisted : PermeabilityState.ALL_RIGHTS;
                visibleIds.forEach(id -> granted.put(id, rights));
                grantedToUnlisted = rights;
            } else {
                visibleIds.forEach(id -> granted.put(id, unlisted != null ? unlisted
                        : inherited == null ? 0 : inherited.granted(id)));
                declared.members().forEach((id, rights) -> {
                    if (visibleIds.contains(id)) {
                        granted.put(id, rights);
                    }
                });
                grantedToUnlisted = unlisted != null ? unlisted : inherited == null ? 0 : inherited.grantedToUnlisted();
            }
            states.put(declared.name(), new PermeabilityState(declared.name(), declared.umask(), granted,
                    grantedToUnlisted, declared.element().line()));
        }
        return new ArrayList<>(states.values());
    }

    private void checkMembers(Declaration.StateDeclaration declared, Set<String> visibleIds) {
        for (XmlElement member : declared.memberElements()) {
            String id = member.attribute("member_id");
            if (!visibleIds.contains(id)) {
                problems.at(member, "state '" + declared.name() + "' names member_id '" + id
                        + "', which is no member of " + declaration.shortName());
            }
        }
    }

    private Set<String> visibleMemberIds() {
        Stream<String> inherited = supertype == null ? Stream.empty()
                : Stream.concat(supertype.primitives().stream().map(Primitive::memberId),
                        supertype.attributes().stream().map(Attribute::memberId));
        Stream<String> own = Stream.concat(declaration.primitives().stream().map(Primitive::memberId),
                declaration.attributes().stream().map(Attribute::memberId));
        return Stream.concat(inherited, own).collect(Collectors.toSet());
    }

    private boolean isInherited(String id) {
        return supertype != null && (supertype.primitives().stream().anyMatch(p -> p.memberId().equals(id))
                || supertype.attributes().stream().anyMatch(a -> a.memberId().equals(id)));
    }

    /** The supertype declaring {@code memberName} nearest to this type, for messages. */
    private String declaringType(String memberName) {
        for (AgentType type = supertype; type != null; type = type.supertype()) {
            boolean declares = type.declaredPrimitives().stream().anyMatch(p -> p.name().equals(memberName))
                    || type.declaredAttributes().stream().anyMatch(a -> a.name().equals(memberName));
            if (declares) {
                return type.shortName() + " (" + type.source().displayName() + ":" + lineOf(type, memberName) + ")";
            }
        }
        return supertype.shortName();
    }

    private static int lineOf(AgentType type, String memberName) {
        return Stream.concat(
                type.declaredPrimitives().stream().filter(p -> p.name().equals(memberName)).map(Primitive::line),
                type.declaredAttributes().stream().filter(a -> a.name().equals(memberName)).map(Attribute::line))
                .findFirst().orElse(type.line());
    }

}
