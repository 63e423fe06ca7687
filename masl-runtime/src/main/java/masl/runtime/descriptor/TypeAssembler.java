package masl.runtime.descriptor;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/**
 * Puts a {@link Declaration} together with its resolved supertype into an {@link AgentType}, checking
 * the rules that involve inherited members: redefinitions (same kind), member ids unique in the type
 * and its supertypes, {@code <Member>} ids, countermeasures. Builds the permeability states by the
 * inheritance rule of {@link AgentType#states()}.
 *
 * <p>Member ids belong to the descriptor that declares them: a redefinition may take a new id, a
 * state names the ids of its own descriptor's members, and an inherited state's rights pass to this
 * type's members by name, whatever id a redefinition gave them.
 */
final class TypeAssembler {

    private final Declaration declaration;
    private final AgentType supertype;
    private final Problems problems;
    /** This type's members, inherited then new, by name: their member ids here. */
    private final Map<String, String> idByName;

    private TypeAssembler(Declaration declaration, AgentType supertype, Problems problems) {
        this.declaration = declaration;
        this.supertype = supertype;
        this.problems = problems;
        this.idByName = new LinkedHashMap<>();
        if (supertype != null) {
            idByName.putAll(memberIds(supertype.primitives(), supertype.attributes()));
        }
        idByName.putAll(memberIds(declaration.primitives(), declaration.attributes()));
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

    private static Map<String, String> memberIds(List<Primitive> primitives, List<Attribute> attributes) {
        Map<String, String> ids = new LinkedHashMap<>();
        primitives.forEach(p -> ids.put(p.name(), p.memberId()));
        attributes.forEach(a -> ids.put(a.name(), a.memberId()));
        return ids;
    }

    private void checkAgainstInherited() {
        if (supertype == null) {
            return;
        }
        Map<String, String> ancestorNameById = ancestorNameById();
        for (Primitive primitive : declaration.primitives()) {
            XmlElement element = declaration.memberElementAt(primitive.line(), primitive.column());
            if (supertype.findAttribute(primitive.name()).isPresent()) {
                problems.at(element, "primitive '" + primitive.name() + "' has the name of an attribute inherited from "
                        + declaringType(primitive.name()));
            } else {
                checkId(element, primitive.name(), primitive.memberId(), ancestorNameById);
            }
        }
        for (Attribute attribute : declaration.attributes()) {
            XmlElement element = declaration.memberElementAt(attribute.line(), attribute.column());
            if (supertype.findPrimitive(attribute.name()).isPresent()) {
                problems.at(element, "attribute '" + attribute.name() + "' has the name of a primitive inherited from "
                        + declaringType(attribute.name()));
            } else {
                checkId(element, attribute.name(), attribute.memberId(), ancestorNameById);
            }
        }
    }

    /** Every member id declared by a supertype, with the name of its member (the nearest declaration's). */
    private Map<String, String> ancestorNameById() {
        Map<String, String> names = new HashMap<>();
        for (AgentType type = supertype; type != null; type = type.supertype()) {
            type.declaredPrimitives().forEach(p -> names.putIfAbsent(p.memberId(), p.name()));
            type.declaredAttributes().forEach(a -> names.putIfAbsent(a.memberId(), a.name()));
        }
        return names;
    }

    /**
     * Member ids are unique in the type and its supertypes (agent-types.md): a member may only take an
     * id a supertype used for the member it redefines. A redefinition may keep the inherited id or
     * take one of its own.
     */
    private void checkId(XmlElement element, String name, String id, Map<String, String> ancestorNameById) {
        String owner = ancestorNameById.get(id);
        if (owner != null && !owner.equals(name)) {
            problems.at(element, "duplicate member_id '" + id + "': already used by '" + owner + "' of "
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
        Map<String, PermeabilityState> states = new LinkedHashMap<>();
        if (supertype != null) {
            for (PermeabilityState inherited : supertype.states()) {
                states.put(inherited.name(), inheritedState(inherited));
            }
        }
        for (Declaration.StateDeclaration declared : declaration.states()) {
            checkMembers(declared);
            PermeabilityState inherited = states.get(declared.name());
            Map<String, Integer> granted = new HashMap<>();
            int grantedToUnlisted;
            Integer unlisted = declared.unlistedRights();
            if (declared.members().isEmpty()) {
                int rights = unlisted != null ? unlisted : PermeabilityState.ALL_RIGHTS;
                idByName.values().forEach(id -> granted.put(id, rights));
                grantedToUnlisted = rights;
            } else {
                idByName.values().forEach(id -> granted.put(id, unlisted != null ? unlisted
                        : inherited == null ? 0 : inherited.granted(id)));
                declared.members().forEach((id, rights) -> {
                    if (idByName.containsValue(id)) {
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

    /**
     * A supertype's state as this type has it: each inherited member keeps its rights under the id it
     * has here (a redefinition's own id included); a new member gets what the state gives unlisted ones.
     */
    private PermeabilityState inheritedState(PermeabilityState inherited) {
        Map<String, String> inheritedIds = memberIds(supertype.primitives(), supertype.attributes());
        Map<String, Integer> granted = new HashMap<>();
        idByName.forEach((name, id) -> {
            String inheritedId = inheritedIds.get(name);
            granted.put(id, inheritedId == null ? inherited.grantedToUnlisted() : inherited.granted(inheritedId));
        });
        return new PermeabilityState(inherited.name(), inherited.umask(), granted, inherited.grantedToUnlisted(),
                inherited.line());
    }

    /** A state names the ids of this type's members: its own declarations' and the inherited ones it keeps. */
    private void checkMembers(Declaration.StateDeclaration declared) {
        Map<String, String> inheritedIds = supertype == null ? Map.of()
                : memberIds(supertype.primitives(), supertype.attributes());
        for (XmlElement member : declared.memberElements()) {
            String id = member.attribute("member_id");
            if (idByName.containsValue(id)) {
                continue;
            }
            String redefined = inheritedIds.entrySet().stream().filter(entry -> entry.getValue().equals(id))
                    .map(Map.Entry::getKey).findFirst().orElse(null);
            problems.at(member, "state '" + declared.name() + "' names member_id '" + id + "', which is no member of "
                    + declaration.shortName() + (redefined == null ? ""
                            : ": it is the id of '" + redefined + "' in " + declaringType(redefined) + ", which "
                                    + declaration.shortName() + " redefines as '" + idByName.get(redefined) + "'"));
        }
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
