package masl.translator.analysis;

import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import masl.grammar.MASLParser;
import masl.translator.diagnostics.Suggestions;

/**
 * Resolves type names (MASL §4): Java primitives, the program's agent types, the utility classes of
 * the imported descriptors (by simple or full name), {@code java.lang.*}, {@code java.util.*} and fully
 * qualified class names, found by reflection with the class loader of the agent implementations.
 */
final class TypeNames {

    private static final Map<String, MaslType> PRIMITIVES = Map.of("boolean", MaslType.BOOLEAN,
            "byte", MaslType.BYTE, "char", MaslType.CHAR, "short", MaslType.SHORT, "int", MaslType.INT,
            "long", MaslType.LONG, "float", MaslType.FLOAT, "double", MaslType.DOUBLE, "void", MaslType.VOID);

    private final Map<String, ImportedType> agentTypes;
    private final Map<String, ImportedType> agentTypesByClass = new HashMap<>();
    private final Map<String, String> utilityClassesBySimpleName = new HashMap<>();
    private final ClassLoader classes;

    TypeNames(Map<String, ImportedType> agentTypes, ClassLoader classes) {
        this.agentTypes = agentTypes;
        this.classes = classes;
        for (ImportedType type : agentTypes.values()) {
            if (type.isLoaded()) {
                agentTypesByClass.putIfAbsent(type.descriptor().fullClassName(), type);
                for (String utility : type.descriptor().utilityClasses()) {
                    utilityClassesBySimpleName.putIfAbsent(utility.substring(utility.lastIndexOf('.') + 1), utility);
                }
            }
        }
    }

    /** The names the program gives its agent types, for hints. */
    Set<String> agentTypeNames() {
        return agentTypes.keySet();
    }

    /** The agent type the program calls {@code name}. */
    Optional<ImportedType> agentType(String name) {
        return Optional.ofNullable(agentTypes.get(name));
    }

    /** A type written in the program, or empty when nothing has that name. */
    Optional<MaslType> resolve(String name) {
        MaslType primitive = PRIMITIVES.get(name);
        if (primitive != null) {
            return Optional.of(primitive);
        }
        ImportedType agentType = agentTypes.get(name);
        if (agentType != null) {
            return Optional.of(new MaslType.AgentRef(agentType));
        }
        String utility = utilityClassesBySimpleName.get(name);
        if (utility != null) {
            return javaClass(utility);
        }
        if (name.contains(".")) {
            return javaClass(name);
        }
        return javaClass("java.lang." + name).or(() -> javaClass("java.util." + name));
    }

    /**
     * A type as a descriptor writes it, normalised ({@code int}, {@code java.lang.String}, {@code int[]}).
     * The loader has checked it against the implementation, so only an agent class needs care: it is
     * typed as the program's agent type of that class, when there is one.
     */
    MaslType fromDescriptor(String typeName) {
        if (typeName.endsWith("[]")) {
            return new MaslType.ArrayOf(fromDescriptor(typeName.substring(0, typeName.length() - 2)));
        }
        ImportedType agentType = agentTypesByClass.get(typeName);
        if (agentType != null) {
            return new MaslType.AgentRef(agentType);
        }
        return resolve(typeName).orElse(MaslType.OBJECT);
    }

    /** A type written in the program; reports an unknown name and gives {@link MaslType#ERROR} for it. */
    MaslType resolve(MASLParser.JavaTypeContext javaType, Errors errors) {
        MaslType element;
        if (javaType.primitiveType() != null) {
            element = PRIMITIVES.get(javaType.primitiveType().getText());
        } else {
            String name = javaType.qualifiedName().getText();
            element = resolve(name).orElse(null);
            if (element == null) {
                errors.at(javaType.qualifiedName(), "cannot find type " + name + hint(name));
                return MaslType.ERROR;
            }
            checkTypeArguments(javaType.typeArguments(), errors);
        }
        int dimensions = javaType.dims() == null ? 0 : javaType.dims().LBRACK().size();
        return arrayOf(element, dimensions);
    }

    /** A hint among the agent types, the primitive types and the utility classes' simple names. */
    String hint(String name) {
        Set<String> known = new LinkedHashSet<>(agentTypes.keySet());
        known.addAll(PRIMITIVES.keySet());
        known.addAll(utilityClassesBySimpleName.keySet());
        known.addAll(JavaLibraryNames.simpleNames());
        return Suggestions.hint(name, known);
    }

    /** Type arguments are erased (§3 types at run time what Java would type by its generics), but must exist. */
    private void checkTypeArguments(MASLParser.TypeArgumentsContext arguments, Errors errors) {
        if (arguments == null) {
            return;
        }
        for (MASLParser.TypeArgumentContext argument : arguments.typeArgument()) {
            if (argument.javaType() != null) {
                resolve(argument.javaType(), errors);
            }
        }
    }

    static MaslType arrayOf(MaslType element, int dimensions) {
        MaslType type = element;
        for (int i = 0; i < dimensions; i++) {
            type = new MaslType.ArrayOf(type);
        }
        return type;
    }

    private Optional<MaslType> javaClass(String name) {
        String binaryName = name;
        while (true) {
            try {
                return Optional.of(MaslType.of(Class.forName(binaryName, false, classes)));
            } catch (ClassNotFoundException | LinkageError notThisName) {
                // A nested class is written Outer.Inner but named Outer$Inner: try the next reading.
                int lastDot = binaryName.lastIndexOf('.');
                if (lastDot < 0) {
                    return Optional.empty();
                }
                binaryName = binaryName.substring(0, lastDot) + '$' + binaryName.substring(lastDot + 1);
            }
        }
    }
}
