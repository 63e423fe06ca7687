package masl.translator.generate;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;
import masl.grammar.MASLParser.ExpressionContext;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Attribute;
import masl.runtime.descriptor.Parameter;
import masl.runtime.descriptor.Primitive;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.ImportedType;
import masl.translator.analysis.MaslType;
import masl.translator.analysis.Member;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * Translates the members of agents that expressions use (§8.4, §9): primitive invocations and
 * attribute reads and writes, of the current agent or of another, through the runtime's helpers
 * that filter them by permeability (contract §8). For another agent, the member may be declared by
 * a type the receiver may be of (§4): the helper's class test then makes it a {@code nop()} for
 * the agents that lack it.
 */
final class AgentMemberWriter {

    private final AnalyzedProgram program;
    private final ImportedType selfType;
    private final Unsupported unsupported;
    private final ExpressionWriter expressions;
    private final TreeQueries queries;
    private final AgentCalls calls;

    AgentMemberWriter(AnalyzedProgram program, ImportedType selfType, Unsupported unsupported,
            ExpressionWriter expressions) {
        this.program = program;
        this.selfType = selfType;
        this.unsupported = unsupported;
        this.expressions = expressions;
        this.queries = expressions.queries();
        this.calls = expressions.calls();
    }

    /**
     * An invocation of primitive {@code name} (§9) of {@code receiver}'s agent, or of the current
     * agent when {@code receiver} is null or {@code this}: through the runtime, which filters it by
     * permeability (contract §8.1). A synchronous external one, and an asynchronous one whose value
     * is used, are suspension points: the expression reads the future's value once awaited.
     */
    String primitiveCall(ExpressionContext receiver, String name, List<ExpressionContext> arguments,
            ParserRuleContext where) {
        boolean internal = receiver == null || TreeQueries.isThis(receiver);
        if (!internal && queries.namedType(receiver) != null) {
            // Permeability filters an invocation by its callee: a type is none (as for static attributes).
            return unsupported.report(where, "an invocation of a primitive through its type");
        }
        var receiverType = internal ? selfType.descriptor() : queries.descriptorOf(receiver);
        // Polymorphism (MASL 4): for another agent, a type the receiver may be of may declare it.
        var calleeType = declaringType(receiverType, receiver, where, type -> type.findPrimitive(name).isPresent());
        Optional<Primitive> found = calleeType == null ? Optional.empty() : calleeType.findPrimitive(name);
        if (found.isEmpty()) {
            return unsupported.report(where, internal
                    ? "a primitive call the agent's type lacks, inside an expression,"
                    : "an invocation of a primitive that the receiver's declared type lacks");
        }
        Primitive primitive = found.get();
        String callee = internal ? "self" : expressions.expr(receiver);
        List<String> java = arguments(primitive, arguments);
        String calleeClass = calleeType.fullClassName();
        String receiverClass = receiverClass(receiverType, calleeType);
        if (primitive.synchronous() && internal) {
            return calls.call(AgentCalls.Kind.INVOKE_SELF, primitive, null, calleeClass, callee, java);
        }
        if (primitive.synchronous()) {
            String invocation = calls.call(AgentCalls.Kind.INVOKE, primitive, null, calleeClass, receiverClass, callee, java);
            return expressions.awaited(invocation, primitive, where);
        }
        Primitive countermeasure = primitive.countermeasure() == null ? null
                : calleeType.findPrimitive(primitive.countermeasure()).orElse(null);
        String launch = calls.call(AgentCalls.Kind.LAUNCH, primitive, countermeasure, calleeClass, receiverClass,
                callee, java);
        return expressions.isUnawaited(where) ? launch : expressions.awaited(launch, primitive, where);
    }

    private List<ImportedType> declaringTypes(ParserRuleContext call) {
        return program.symbolOf(call).orElse(null) instanceof Member member ? member.declaringTypes() : List.of();
    }

    /** The arguments of a call, converted for the primitive's parameters (§3). */
    List<String> arguments(Primitive primitive, List<ExpressionContext> arguments) {
        List<Parameter> parameters = primitive.parameters();
        List<String> java = new ArrayList<>();
        for (int i = 0; i < arguments.size(); i++) {
            MaslType parameter = parameterType(parameters.get(i).type());
            java.add(parameter == null ? expressions.expr(arguments.get(i))
                    : expressions.converted(parameter, arguments.get(i)));
        }
        return java;
    }

    /** A read of attribute {@code name} of {@code owner}'s agent (the current one when null or {@code this}), §8.4. */
    String attributeRead(ExpressionContext owner, String name, ParserRuleContext where) {
        boolean own = owner == null || TreeQueries.isThis(owner);
        var receiverType = own ? selfType.descriptor() : queries.descriptorOf(owner);
        var ownerType = declaringType(receiverType, owner, where, type -> type.findAttribute(name).isPresent());
        if (ownerType == null) {
            return unsupported.report(where, "an attribute that the owner's declared type lacks");
        }
        Attribute attribute = ownerType.findAttribute(name).orElseThrow();
        String constant = constant(attribute);
        if (constant != null) {
            return constant;
        }
        if (!own && queries.namedType(owner) != null) {
            return unsupported.report(where, "a static attribute read through its type, unless a constant,");
        }
        return calls.read(attribute, ownerType.fullClassName(), receiverClass(receiverType, ownerType),
                own ? "self" : expressions.expr(owner));
    }

    /** A write of attribute {@code name} of {@code owner}'s agent, §8.4; {@code value} is Java. */
    String attributeWrite(ExpressionContext owner, String name, String value, ParserRuleContext where) {
        boolean own = owner == null || TreeQueries.isThis(owner);
        var receiverType = own ? selfType.descriptor() : queries.descriptorOf(owner);
        var ownerType = declaringType(receiverType, owner, where, type -> type.findAttribute(name).isPresent());
        if (ownerType == null) {
            return unsupported.report(where, "an attribute that the owner's declared type lacks");
        }
        if (!own && queries.namedType(owner) != null) {
            return unsupported.report(where, "a write of a static attribute through its type");
        }
        return calls.write(ownerType.findAttribute(name).orElseThrow(), ownerType.fullClassName(),
                receiverClass(receiverType, ownerType), own ? "self" : expressions.expr(owner), value);
    }

    /**
     * The type whose member an access uses: the receiver's static type if it has it. For another
     * agent ({@code receiver} neither null nor {@code this}), else a subtype some imported type
     * declaring the member is (§4), else any type declaring it: no agent the receiver may be has the
     * member, so the helper's class test makes the access a {@code nop()} for all. Null for the
     * current agent's member its type lacks, and for a member read through a type that lacks it.
     */
    AgentType declaringType(AgentType receiverType, ExpressionContext receiver, ParserRuleContext where,
            Predicate<AgentType> has) {
        if (receiverType == null || has.test(receiverType)) {
            return receiverType;
        }
        if (receiver == null || TreeQueries.isThis(receiver)) {
            return null;
        }
        AgentType unrelated = null;
        for (ImportedType declaring : declaringTypes(where)) {
            if (declaring.isLoaded() && has.test(declaring.descriptor())) {
                if (declaring.descriptor().isSubtypeOf(receiverType)) {
                    return declaring.descriptor();
                }
                unrelated = unrelated == null ? declaring.descriptor() : unrelated;
            }
        }
        return queries.namedType(receiver) == null ? unrelated : null;
    }

    /**
     * The class a member's helper takes its receiver as: the receiver's static type's, or, when the
     * declaring type is no subtype of it, the root type's (the class test then always fails).
     */
    static String receiverClass(AgentType receiverType, AgentType declaring) {
        if (declaring.isSubtypeOf(receiverType)) {
            return receiverType.fullClassName();
        }
        AgentType root = receiverType;
        while (root.supertype() != null) {
            root = root.supertype();
        }
        return root.fullClassName();
    }

    /** The consumer storing a label's result in attribute {@code name} of an agent (§10): no permeability filter. */
    String attributeStore(ExpressionContext owner, String ownerJava, String name, ParserRuleContext where) {
        var receiverType = owner == null ? selfType.descriptor() : queries.descriptorOf(owner);
        var ownerType = declaringType(receiverType, owner, where, type -> type.findAttribute(name).isPresent());
        if (ownerType == null) {
            return unsupported.report(where, "an attribute that the owner's declared type lacks");
        }
        return calls.store(ownerType.findAttribute(name).orElseThrow(), ownerType.fullClassName(),
                receiverClass(receiverType, ownerType), ownerJava);
    }

    /** The value of a {@code final} attribute with a {@code value}: a Java constant (§9); null otherwise. */
    private static String constant(Attribute attribute) {
        if (!attribute.isFinal() || attribute.value() == null) {
            return null;
        }
        String value = attribute.value().trim();
        return switch (attribute.type()) {
            case "java.lang.String" -> JavaText.quote(attribute.value());
            case "boolean", "int" -> value;
            case "long" -> value + "L";
            case "float" -> value + "f";
            case "double" -> value + "d";
            default -> null;
        };
    }

    private static MaslType parameterType(String descriptorType) {
        return switch (descriptorType) {
            case "java.lang.String" -> MaslType.STRING;
            case "byte" -> MaslType.BYTE;
            case "short" -> MaslType.SHORT;
            case "char" -> MaslType.CHAR;
            default -> null;
        };
    }
}
