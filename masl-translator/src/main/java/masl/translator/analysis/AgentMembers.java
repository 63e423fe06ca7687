package masl.translator.analysis;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.Primitive;

/**
 * The primitives and attributes of the imported agent types, by name. A member may be used on any
 * agent as soon as one imported type has it (MASL §4: on agents of other types the statement is a nop),
 * so a lookup returns every type's declaration of the name, the receiver's own type first.
 */
final class AgentMembers {

    /** One type's declaration of a member. */
    record Declared<M>(ImportedType owner, M member) { }

    private final Collection<ImportedType> types;

    AgentMembers(Collection<ImportedType> types) {
        this.types = types;
    }

    /**
     * @param receiver the receiver's type, or null when unknown (the current agent, an entry list element)
     */
    List<Declared<Primitive>> primitives(String name, ImportedType receiver) {
        List<Declared<Primitive>> found = new ArrayList<>();
        for (ImportedType type : ordered(receiver)) {
            type.descriptor().findPrimitive(name).ifPresent(primitive -> found.add(new Declared<>(type, primitive)));
        }
        return found;
    }

    List<Declared<Attribute>> attributes(String name, ImportedType receiver) {
        List<Declared<Attribute>> found = new ArrayList<>();
        for (ImportedType type : ordered(receiver)) {
            type.descriptor().findAttribute(name).ifPresent(attribute -> found.add(new Declared<>(type, attribute)));
        }
        return found;
    }

    /** The names of every primitive of the loaded types, for hints. */
    Set<String> primitiveNames() {
        Set<String> names = new LinkedHashSet<>();
        ordered(null).forEach(type -> type.descriptor().primitives().forEach(primitive -> names.add(primitive.name())));
        return names;
    }

    /** The names of every attribute of the loaded types, for hints. */
    Set<String> attributeNames() {
        Set<String> names = new LinkedHashSet<>();
        ordered(null).forEach(type -> type.descriptor().attributes().forEach(attribute -> names.add(attribute.name())));
        return names;
    }

    /** Whether some imported type could not be loaded: then any member might be one of its, unknown. */
    boolean someTypeUnknown() {
        return types.stream().anyMatch(type -> !type.isLoaded());
    }

    private List<ImportedType> ordered(ImportedType receiver) {
        List<ImportedType> ordered = new ArrayList<>();
        if (receiver != null && receiver.isLoaded()) {
            ordered.add(receiver);
        }
        for (ImportedType type : types) {
            if (type.isLoaded() && !ordered.contains(type)) {
                ordered.add(type);
            }
        }
        return ordered;
    }

    /** The types declaring {@code declarations}, each once, in their order. */
    static List<ImportedType> owners(List<? extends Declared<?>> declarations) {
        // A loop, not a stream: this runs for every member access, often before the JIT has compiled
        // it, and a stream pipeline costs the interpreter many calls (the cold translation).
        List<ImportedType> owners = new ArrayList<>(declarations.size());
        for (Declared<?> declaration : declarations) {
            if (!owners.contains(declaration.owner())) {
                owners.add(declaration.owner());
            }
        }
        return List.copyOf(owners);
    }
}
