package masl.translator.generate;

import masl.grammar.MASLParser;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Primitive;
import masl.translator.analysis.MaslType;
import masl.translator.analysis.Symbol;
import masl.translator.analysis.TypeRef;
import masl.grammar.MASLParser.ExpressionContext;
import masl.translator.analysis.AgentDecl;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.ImportedType;
import masl.translator.analysis.Member;
import masl.translator.analysis.Variable;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * Questions the generator asks about a piece of the program, for the agent type being generated:
 * does it use a member the type lacks (§4), does it mention a variable, may it throw a checked exception.
 */
final class TreeQueries {

    private final AnalyzedProgram program;
    private final ImportedType selfType;

    TreeQueries(AnalyzedProgram program, ImportedType selfType) {
        this.program = program;
        this.selfType = selfType;
    }

    ImportedType selfType() {
        return selfType;
    }

    /**
     * Whether {@code tree} uses a primitive or attribute of the current agent that this agent's type
     * lacks: the statement is then a {@code nop()} for it, and a test or condition is false (§4).
     * Another agent's missing member is the call's business (a polymorphic receiver gives the default).
     */
    boolean usesAbsentMember(ParseTree tree) {
        if (tree instanceof ParserRuleContext node && isSelfAccess(node)
                && program.symbolOf(node).orElse(null) instanceof Member member && !selfHas(member)) {
            return true;
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (usesAbsentMember(tree.getChild(i))) {
                return true;
            }
        }
        return false;
    }

    private boolean selfHas(Member member) {
        return switch (member.kind()) {
            case PRIMITIVE -> selfType.descriptor().findPrimitive(member.name()).isPresent();
            case ATTRIBUTE -> selfType.descriptor().findAttribute(member.name()).isPresent();
            default -> true;
        };
    }

    private static boolean isSelfAccess(ParserRuleContext node) {
        if (node instanceof MASLParser.PrimaryExprContext primary) {
            return primary.primary() instanceof MASLParser.SelfInvocationContext
                    || primary.primary() instanceof MASLParser.SelfAttributeContext;
        }
        if (node instanceof MASLParser.MethodCallContext call) {
            return isThis(call.expression());
        }
        return node instanceof MASLParser.FieldAccessContext access && isThis(access.expression());
    }

    static boolean isThis(ExpressionContext expression) {
        return expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.ThisExprContext;
    }

    /**
     * The descriptor of the agent {@code receiver} stands for: a named agent's instantiated type (its
     * members are those of the agent it names, MASL §4), else {@link #descriptorOf(MaslType) its static type's}.
     */
    AgentType descriptorOf(ExpressionContext receiver) {
        AgentType named = namedAgentType(receiver);
        if (named == null) {
            named = namedType(receiver);
        }
        return named != null ? named : descriptorOf(program.typeOf(receiver));
    }

    /** The instantiated type of the agent {@code receiver} names ({@code rover} of {@code Robot rover = newAgent(Rover)}), or null. */
    private AgentType namedAgentType(ExpressionContext receiver) {
        return program.symbolOf(receiver).orElse(null) instanceof AgentDecl agent && agent.instantiatedType().isLoaded()
                ? agent.instantiatedType().descriptor() : null;
    }

    /** The agent type {@code receiver} names, as {@code Soft} in {@code Soft.MOVE_COST} (a static member), or null. */
    AgentType namedType(ExpressionContext receiver) {
        return program.symbolOf(receiver).orElse(null) instanceof TypeRef ref
                && ref.type() instanceof MaslType.AgentRef agent && agent.type() != null && agent.type().isLoaded()
                ? agent.type().descriptor() : null;
    }

    /** The descriptor of an agent-typed value's static type: the root type's for "any agent"; null if not an agent. */
    AgentType descriptorOf(MaslType type) {
        if (!(type instanceof MaslType.AgentRef agent)) {
            return null;
        }
        if (agent.type() == null) {
            AgentType root = selfType.descriptor();
            while (root.supertype() != null) {
                root = root.supertype();
            }
            return root;
        }
        return agent.type().isLoaded() ? agent.type().descriptor() : null;
    }

    /** The primitive a call invokes, looked up in the callee's static type; null if it is no primitive call. */
    Primitive invokedPrimitive(ParseTree tree) {
        if (!(tree instanceof ParserRuleContext node && program.symbolOf(node).orElse(null) instanceof Member member
                && member.kind() == Member.Kind.PRIMITIVE)) {
            return null;
        }
        AgentType callee = isInternalCall(node) ? selfType.descriptor()
                : node instanceof MASLParser.MethodCallContext call ? descriptorOf(call.expression())
                : null;
        return callee == null ? null : callee.findPrimitive(member.name()).orElse(null);
    }

    /** A call of the current agent's primitive: {@code .m()} or {@code this.m()}. */
    static boolean isInternalCall(ParserRuleContext node) {
        return node instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.SelfInvocationContext
                || node instanceof MASLParser.MethodCallContext call && isThis(call.expression());
    }

    /**
     * Whether {@code tree} waits for a result (contract §3.11): it invokes another agent's
     * primitive or an asynchronous one, or reads a variable holding a future.
     */
    boolean suspends(ParseTree tree, FutureVariables futures) {
        if (tree instanceof ParserRuleContext node) {
            Symbol symbol = program.symbolOf(node).orElse(null);
            if (symbol instanceof Variable variable && futures.contains(variable)) {
                return true;
            }
            Primitive primitive = invokedPrimitive(node);
            if (primitive != null && (!primitive.synchronous() || !isInternalCall(node))) {
                return true;
            }
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (suspends(tree.getChild(i), futures)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether {@code tree} calls a primitive that is an instruction (contract §8.1): any external
     * invocation or launch, and an internal call unless of a synchronous accessor. A primitive the
     * callee's type lacks counts too: its {@code nop()} has duration, like a statement's (§4).
     */
    boolean callsInstruction(ParseTree tree) {
        if (tree instanceof ParserRuleContext node && program.symbolOf(node).orElse(null) instanceof Member member
                && member.kind() == Member.Kind.PRIMITIVE) {
            Primitive primitive = invokedPrimitive(node);
            if (!isInternalCall(node) || primitive == null || !primitive.accessor() || !primitive.synchronous()) {
                return true;
            }
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (callsInstruction(tree.getChild(i))) {
                return true;
            }
        }
        return false;
    }

    /** Whether {@code tree} reads or writes {@code variable}. */
    boolean mentions(ParseTree tree, Variable variable) {
        if (tree instanceof ParserRuleContext node && program.symbolOf(node).orElse(null) == variable) {
            return true;
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (mentions(tree.getChild(i), variable)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether {@code tree} calls Java code that may throw: a Java method or constructor, or a member
     * of an {@code Object}-typed value. A statement doing so catches the exception as
     * {@code uncaught_exception} (MASL 8, 9); a primitive's exception is the runtime's to catch.
     */
    boolean mayThrow(ParseTree tree) {
        if (tree instanceof ParserRuleContext node && program.symbolOf(node).orElse(null) instanceof Member member
                && (member.kind() == Member.Kind.JAVA_METHOD && member.javaMember() != null
                || member.kind() == Member.Kind.DYNAMIC)) {
            return true;
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (mayThrow(tree.getChild(i))) {
                return true;
            }
        }
        return false;
    }

    boolean throwsChecked(ParseTree tree) {
        if (tree instanceof ParserRuleContext node && program.symbolOf(node).orElse(null) instanceof Member member
                && member.javaMember() != null) {
            for (Class<?> exception : member.javaMember().getExceptionTypes()) {
                if (!RuntimeException.class.isAssignableFrom(exception) && !Error.class.isAssignableFrom(exception)) {
                    return true;
                }
            }
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (throwsChecked(tree.getChild(i))) {
                return true;
            }
        }
        return false;
    }
}
