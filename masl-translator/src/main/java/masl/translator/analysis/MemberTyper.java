package masl.translator.analysis;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.Parameter;
import masl.runtime.descriptor.Primitive;
import masl.translator.diagnostics.Suggestions;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;

/**
 * Types member accesses once the receiver is known: primitives and attributes of agents (MASL §4, §9),
 * entry members (§6.7), label members (§10) and members of Java objects and classes (by reflection).
 * Binds each access to its {@link Member} and reports members that do not exist or do not fit.
 */
final class MemberTyper {

    /** An entry member: whether it is written with parentheses, and its result. */
    private record EntryMember(boolean isCall, MaslType result) { }

    private static final MaslType AGENTS = new MaslType.ArrayOf(MaslType.ANY_AGENT);
    private static final Map<String, EntryMember> ENTRY_MEMBERS = Map.ofEntries(
            Map.entry("count", new EntryMember(false, MaslType.INT)),
            Map.entry("getList", new EntryMember(true, AGENTS)),
            Map.entry("getActiveCount", new EntryMember(true, MaslType.INT)),
            Map.entry("getActiveList", new EntryMember(true, AGENTS)),
            Map.entry("getWaitingInCount", new EntryMember(true, MaslType.INT)),
            Map.entry("getWaitingInList", new EntryMember(true, AGENTS)),
            Map.entry("getWaitingOutCount", new EntryMember(true, MaslType.INT)),
            Map.entry("getWaitingOutList", new EntryMember(true, AGENTS)),
            Map.entry("getLockPolicy", new EntryMember(true, MaslType.STRING)),
            Map.entry("lock", new EntryMember(true, MaslType.VOID)),
            Map.entry("release", new EntryMember(true, MaslType.VOID)));
    private static final String ENTRY_MEMBER_LIST = "count, getList(), getActiveCount(), getActiveList(), "
            + "getWaitingInCount(), getWaitingInList(), getWaitingOutCount(), getWaitingOutList(), getLockPolicy(), "
            + "lock(), release() and release(n)";

    private final Bindings bindings;
    private final Errors errors;
    private final AgentMembers agentMembers;
    private final TypeNames typeNames;

    MemberTyper(Bindings bindings, Errors errors, AgentMembers agentMembers, TypeNames typeNames) {
        this.bindings = bindings;
        this.errors = errors;
        this.agentMembers = agentMembers;
        this.typeNames = typeNames;
    }

    /**
     * An invocation of primitive {@code name}: fine when one imported type's primitive of that name accepts
     * the arguments (a {@code String} parameter accepts anything, §3).
     *
     * @param receiver the receiver's agent type, null for the current agent or an agent of unknown type
     */
    MaslType primitive(ImportedType receiver, Token name, List<MaslType> arguments,
            List<? extends ParserRuleContext> argumentTrees, ParserRuleContext access) {
        List<AgentMembers.Declared<Primitive>> declared = agentMembers.primitives(name.getText(), receiver);
        if (declared.isEmpty()) {
            reportMissingAgentMember("primitive", name);
            return MaslType.ERROR;
        }
        bindings.bind(access, new Member(Member.Kind.PRIMITIVE, name.getText(), AgentMembers.owners(declared), null));
        for (AgentMembers.Declared<Primitive> candidate : declared) {
            if (accepts(candidate.member(), arguments)) {
                return typeNames.fromDescriptor(candidate.member().returnType());
            }
        }
        Primitive expected = declared.get(0).member();
        reportMismatch(expected, arguments, argumentTrees, name);
        return typeNames.fromDescriptor(expected.returnType());
    }

    /** A read or a write of attribute {@code name}; writing a {@code final} attribute is an error. */
    MaslType attribute(ImportedType receiver, Token name, boolean isWrite, ParserRuleContext access) {
        Attribute attribute = declaredAttribute(receiver, name, isWrite, access);
        return attribute == null ? MaslType.ERROR : typeNames.fromDescriptor(attribute.type());
    }

    /**
     * An attribute read or written through its agent type's name ({@code Worker.LIMIT}): only a static
     * one belongs to the type; another is each agent's own, used on an agent ({@code w.battery}).
     */
    MaslType staticAttribute(ImportedType type, Token name, boolean isWrite, ParserRuleContext access) {
        Attribute attribute = declaredAttribute(type, name, isWrite, access);
        if (attribute == null) {
            return MaslType.ERROR;
        }
        if (!attribute.isStatic()) {
            errors.at(name, name.getText() + " is not a static attribute of " + type.name()
                    + ": each agent has its own, used on an agent of that type (a." + name.getText()
                    + ", or ." + name.getText() + " for the current agent's)");
            return MaslType.ERROR;
        }
        return typeNames.fromDescriptor(attribute.type());
    }

    /**
     * The attribute {@code name} of {@code receiver} (or of any imported type), bound to {@code access};
     * null, reported, if no type has it. Writing a {@code final} one is reported.
     */
    private Attribute declaredAttribute(ImportedType receiver, Token name, boolean isWrite, ParserRuleContext access) {
        List<AgentMembers.Declared<Attribute>> declared = agentMembers.attributes(name.getText(), receiver);
        if (declared.isEmpty()) {
            reportMissingAgentMember("attribute", name);
            return null;
        }
        bindings.bind(access, new Member(Member.Kind.ATTRIBUTE, name.getText(), AgentMembers.owners(declared), null));
        Attribute attribute = declared.get(0).member();
        if (isWrite && attribute.isFinal()) {
            errors.at(name, "cannot assign a value to final attribute " + name.getText());
        }
        return attribute;
    }

    /**
     * An entry member (§6.7).
     *
     * @param arguments the arguments' types, or null for the form without parentheses ({@code e.count})
     */
    MaslType entryMember(EntryRef entry, Token name, List<MaslType> arguments, ParserRuleContext access) {
        EntryMember member = ENTRY_MEMBERS.get(name.getText());
        if (member == null) {
            String hint = Suggestions.hint(name.getText(), ENTRY_MEMBERS.keySet());
            errors.at(name, "entry " + entry.name() + " has no member " + name.getText()
                    + (hint.isEmpty() ? "; entry members are " + ENTRY_MEMBER_LIST : hint));
            return MaslType.ERROR;
        }
        bindings.bind(access, new Member(Member.Kind.ENTRY_MEMBER, name.getText(), List.of(), null));
        boolean isCall = arguments != null;
        if (isCall != member.isCall()) {
            String written = entry.name() + "." + name.getText();
            errors.at(name, member.isCall() ? name.getText() + " is a method: write " + written + "()"
                    : name.getText() + " is not a method: write " + written);
        } else if (isCall && !acceptsEntryArguments(name.getText(), arguments)) {
            errors.at(name, name.getText().equals("release")
                    ? "release takes no argument or one number of agents"
                    : name.getText() + "() takes no arguments");
        }
        return member.result();
    }

    private static boolean acceptsEntryArguments(String name, List<MaslType> arguments) {
        if (name.equals("release") && arguments.size() == 1) {
            return TypeRules.isOpen(arguments.get(0)) || TypeRules.isIntegral(arguments.get(0));
        }
        return arguments.isEmpty();
    }

    /**
     * {@code l.isFinished()}, {@code l.getRemainingInvocations()} or {@code l.free()}; other names are
     * primitives launched by the label.
     */
    MaslType labelMember(Label label, Token name, List<MaslType> arguments, ParserRuleContext access) {
        bindings.bind(access, new Member(Member.Kind.LABEL_MEMBER, name.getText(), List.of(), null));
        if (!arguments.isEmpty()) {
            errors.at(name, name.getText() + "() of label " + label.name() + " takes no arguments");
        }
        return switch (name.getText()) {
            case "isFinished" -> MaslType.BOOLEAN;
            case "getRemainingInvocations" -> MaslType.INT;
            default -> MaslType.VOID;
        };
    }

    static boolean isLabelMember(String name) {
        return name.equals("isFinished") || name.equals("getRemainingInvocations") || name.equals("free");
    }

    /** A method of a Java class, on an object or (when {@code staticOnly}) on the class itself. */
    /** Whether some imported agent type has a primitive called {@code name}. */
    boolean isPrimitive(String name) {
        return agentMembers.primitiveNames().contains(name);
    }

    MaslType javaMethod(Class<?> owner, boolean staticOnly, Token name, List<MaslType> arguments,
            ParserRuleContext access) {
        JavaMembers.Lookup lookup = JavaMembers.method(owner, name.getText(), arguments, staticOnly);
        String described = MaslType.of(owner).describe();
        if (lookup instanceof JavaMembers.Lookup.Found found) {
            bindings.bind(access, new Member(Member.Kind.JAVA_METHOD, name.getText(), List.of(), found.member()));
            return JavaMembers.resultOf(found.member());
        }
        if (lookup instanceof JavaMembers.Lookup.Missing) {
            errors.at(name, "cannot find method " + name.getText() + describe(arguments) + " in "
                    + (staticOnly ? "class " : "") + described);
        } else {
            errors.at(name, "no method " + described + "." + name.getText() + " accepts " + describe(arguments));
        }
        return MaslType.ERROR;
    }

    /** A public field of a Java class, on an object or (when {@code staticOnly}) on the class itself. */
    MaslType javaField(Class<?> owner, boolean staticOnly, Token name, boolean isWrite, ParserRuleContext access) {
        Optional<Field> field = JavaMembers.field(owner, name.getText(), staticOnly);
        if (field.isEmpty()) {
            errors.at(name, "cannot find field " + name.getText() + " in " + MaslType.of(owner).describe());
            return MaslType.ERROR;
        }
        bindings.bind(access, new Member(Member.Kind.JAVA_FIELD, name.getText(), List.of(), null));
        if (isWrite && Modifier.isFinal(field.get().getModifiers())) {
            errors.at(name, "cannot assign a value to final field " + name.getText());
        }
        return MaslType.of(field.get().getType());
    }

    /** A member of an {@code Object}-typed receiver, resolved at run time (§3). */
    MaslType dynamic(Token name, ParserRuleContext access) {
        bindings.bind(access, new Member(Member.Kind.DYNAMIC, name.getText(), List.of(), null));
        return MaslType.OBJECT;
    }

    static String describe(List<MaslType> arguments) {
        return arguments.stream().map(MaslType::describe).collect(Collectors.joining(", ", "(", ")"));
    }

    /**
     * A member no loaded type has. When a descriptor failed to load, the member may be one of its type's:
     * that failure was reported, and this would only repeat it.
     */
    private void reportMissingAgentMember(String kind, Token name) {
        if (!agentMembers.someTypeUnknown()) {
            Set<String> known = kind.equals("primitive") ? agentMembers.primitiveNames() : agentMembers.attributeNames();
            errors.at(name, "cannot find " + kind + " " + name.getText() + " in any imported agent type"
                    + Suggestions.hint(name.getText(), known));
        }
    }

    private boolean accepts(Primitive primitive, List<MaslType> arguments) {
        List<Parameter> parameters = primitive.parameters();
        if (parameters.size() != arguments.size()) {
            return false;
        }
        for (int i = 0; i < parameters.size(); i++) {
            if (!TypeRules.isAssignable(typeNames.fromDescriptor(parameters.get(i).type()), arguments.get(i), true)) {
                return false;
            }
        }
        return true;
    }

    private void reportMismatch(Primitive expected, List<MaslType> arguments,
            List<? extends ParserRuleContext> argumentTrees, Token name) {
        List<Parameter> parameters = expected.parameters();
        if (parameters.size() != arguments.size()) {
            errors.at(name, "primitive " + expected.signature() + " takes " + parameters.size()
                    + (parameters.size() == 1 ? " argument" : " arguments") + ", found " + arguments.size());
            return;
        }
        for (int i = 0; i < parameters.size(); i++) {
            MaslType parameter = typeNames.fromDescriptor(parameters.get(i).type());
            if (!TypeRules.isAssignable(parameter, arguments.get(i), true)) {
                errors.at(argumentTrees.get(i), "argument " + (i + 1) + " of primitive " + expected.signature()
                        + " must be " + parameter.describe() + ", found " + arguments.get(i).describe());
                return;
            }
        }
    }
}
