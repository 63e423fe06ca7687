package masl.translator.generate;

import java.lang.reflect.Executable;
import masl.grammar.MASLParser;
import masl.grammar.MaslRuleContext;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Primitive;
import masl.translator.analysis.MaslType;
import masl.translator.analysis.Symbol;
import masl.translator.analysis.TypeRef;
import masl.grammar.MASLParser.ExpressionContext;
import masl.translator.analysis.AgentDecl;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.ImportedType;
import masl.translator.analysis.Label;
import masl.translator.analysis.Member;
import masl.translator.analysis.Variable;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * Questions the generator asks about a piece of the program, for the agent type being generated:
 * does it use a member the type lacks (§4), does it mention a variable, may it throw a checked exception.
 */
final class TreeQueries {

    // What a subtree holds, as bits: a statement is asked several questions, and a block about every
    // statement in it, so each node's answers are worked out once and kept by the node's number.
    private static final int KNOWN = 1;
    private static final int USES_ABSENT_MEMBER = 1 << 1;
    private static final int MAY_THROW = 1 << 2;
    private static final int THROWS_CHECKED = 1 << 3;
    private static final int CALLS_INSTRUCTION = 1 << 4;

    private final AnalyzedProgram program;
    private final ImportedType selfType;
    /** The bits of each subtree asked about, by node number; 0 for one not yet asked about. */
    private final int[] facts;
    /** Whether each subtree asked about suspends (1 no, 2 yes), for the future variables of {@link #suspendsFor}. */
    private int[] suspends;
    private FutureVariables suspendsFor;

    TreeQueries(AnalyzedProgram program, ImportedType selfType) {
        this.program = program;
        this.selfType = selfType;
        this.facts = new int[program.parsed().nodes()];
    }

    ImportedType selfType() {
        return selfType;
    }

    /**
     * Whether {@code tree} uses a primitive or attribute of the current agent that this agent's type
     * lacks, label forms on it included ({@code l.m()}, {@code l.this.m()}, {@code l.this.x = …}, §10):
     * the statement is then a {@code nop()} for it, and a test or condition is false (§4).
     * Another agent's missing member is the call's business (a polymorphic receiver gives the default).
     */
    boolean usesAbsentMember(ParseTree tree) {
        return (facts(tree) & USES_ABSENT_MEMBER) != 0;
    }

    private boolean selfHas(Member member) {
        return switch (member.kind()) {
            case PRIMITIVE -> selfType.descriptor().findPrimitive(member.name()).isPresent();
            case ATTRIBUTE -> selfType.descriptor().findAttribute(member.name()).isPresent();
            default -> true;
        };
    }

    private boolean isSelfAccess(ParserRuleContext node) {
        if (node instanceof MASLParser.PrimaryExprContext primary) {
            return primary.primary() instanceof MASLParser.SelfInvocationContext
                    || primary.primary() instanceof MASLParser.SelfAttributeContext;
        }
        if (node instanceof MASLParser.MethodCallContext call) {
            return isThis(call.expression()) || call.expression() instanceof MASLParser.LabelSelfContext
                    || program.symbol(call.expression()) instanceof Label;
        }
        return node instanceof MASLParser.FieldAccessContext access
                && (isThis(access.expression()) || access.expression() instanceof MASLParser.LabelSelfContext);
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
        return program.symbol(receiver) instanceof AgentDecl agent && agent.instantiatedType().isLoaded()
                ? agent.instantiatedType().descriptor() : null;
    }

    /** The agent type {@code receiver} names, as {@code Soft} in {@code Soft.MOVE_COST} (a static member), or null. */
    AgentType namedType(ExpressionContext receiver) {
        return program.symbol(receiver) instanceof TypeRef ref
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
        if (!(tree instanceof ParserRuleContext node && program.symbol(node) instanceof Member member
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
        if (!(tree instanceof MaslRuleContext node)) {
            return false;
        }
        if (futures != suspendsFor) {
            suspends = new int[facts.length];
            suspendsFor = futures;
        }
        int known = suspends[node.index()];
        if (known != 0) {
            return known == 2;
        }
        boolean found = suspendsHere(node, futures);
        for (int i = 0; i < node.getChildCount() && !found; i++) {
            found = suspends(node.getChild(i), futures);
        }
        suspends[node.index()] = found ? 2 : 1;
        return found;
    }

    private boolean suspendsHere(ParserRuleContext node, FutureVariables futures) {
        if (program.symbol(node) instanceof Variable variable && futures.contains(variable)) {
            return true;
        }
        Primitive primitive = invokedPrimitive(node);
        return primitive != null && (!primitive.synchronous() || !isInternalCall(node));
    }

    /**
     * Whether {@code tree} calls a primitive that is an instruction (contract §8.1): any external
     * invocation or launch, and an internal call unless of a synchronous accessor. A primitive the
     * callee's type lacks counts too: its {@code nop()} has duration, like a statement's (§4).
     */
    boolean callsInstruction(ParseTree tree) {
        return (facts(tree) & CALLS_INSTRUCTION) != 0;
    }

    /** Whether {@code tree} reads or writes {@code variable}. */
    boolean mentions(ParseTree tree, Variable variable) {
        if (tree instanceof ParserRuleContext node && program.symbol(node) == variable) {
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
        return (facts(tree) & MAY_THROW) != 0;
    }

    /** Whether {@code tree} calls a Java method or constructor declaring a checked exception. */
    boolean throwsChecked(ParseTree tree) {
        return (facts(tree) & THROWS_CHECKED) != 0;
    }

    /** The bits of {@code tree}: its node's own, and its children's. */
    private int facts(ParseTree tree) {
        if (!(tree instanceof MaslRuleContext node)) {
            return 0;
        }
        int known = facts[node.index()];
        if (known != 0) {
            return known;
        }
        int found = KNOWN | factsHere(node);
        for (int i = 0; i < node.getChildCount(); i++) {
            found |= facts(node.getChild(i));
        }
        facts[node.index()] = found;
        return found;
    }

    private int factsHere(ParserRuleContext node) {
        if (!(program.symbol(node) instanceof Member member)) {
            return 0;
        }
        int found = 0;
        if (isSelfAccess(node) && !selfHas(member)) {
            found |= USES_ABSENT_MEMBER;
        }
        if (member.kind() == Member.Kind.JAVA_METHOD && member.javaMember() != null
                || member.kind() == Member.Kind.DYNAMIC) {
            found |= MAY_THROW;
        }
        if (member.javaMember() != null && declaresCheckedException(member.javaMember())) {
            found |= THROWS_CHECKED;
        }
        if (member.kind() == Member.Kind.PRIMITIVE) {
            Primitive primitive = invokedPrimitive(node);
            if (!isInternalCall(node) || primitive == null || !primitive.accessor() || !primitive.synchronous()) {
                found |= CALLS_INSTRUCTION;
            }
        }
        return found;
    }

    private static boolean declaresCheckedException(Executable method) {
        for (Class<?> exception : method.getExceptionTypes()) {
            if (!RuntimeException.class.isAssignableFrom(exception) && !Error.class.isAssignableFrom(exception)) {
                return true;
            }
        }
        return false;
    }
}
