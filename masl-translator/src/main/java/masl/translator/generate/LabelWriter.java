package masl.translator.generate;

import java.util.List;
import java.util.Map;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Primitive;
import masl.translator.analysis.AgentDecl;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.ImportedType;
import masl.translator.analysis.Label;
import masl.translator.analysis.Sharing;
import masl.translator.analysis.Symbol;
import masl.translator.analysis.Variable;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * Translates MASL's labels (§10) for the program of one agent type: an {@code LLabel} is a field of
 * the program, an {@code SLabel} the wave's shared label, and a launch through a label form
 * ({@code l.a.m(…)}, {@code l.x = a.m(…)}) registers the invocation with the label (contract §8.3).
 */
final class LabelWriter {

    private final AnalyzedProgram program;
    private final StaticStructure structure;
    private final ImportedType selfType;
    private final Unsupported unsupported;
    private final ExpressionWriter expressions;
    private final AgentMemberWriter members;
    private final Map<Label, String> localLabels = new java.util.LinkedHashMap<>();

    LabelWriter(AnalyzedProgram program, StaticStructure structure, ImportedType selfType, Unsupported unsupported,
            ExpressionWriter expressions, AgentMemberWriter members) {
        this.program = program;
        this.structure = structure;
        this.selfType = selfType;
        this.unsupported = unsupported;
        this.expressions = expressions;
        this.members = members;
    }

    /** The field of an {@code LLabel}: {@code block$name}. */
    String localLabel(Label label) {
        return localLabels.computeIfAbsent(label, l -> expressions.field(l.block().name() + "$" + l.name()));
    }

    /** The {@code LLabel}s used so far, with their fields. */
    Map<Label, String> localLabels() {
        return localLabels;
    }

    /** The label a name stands for, or null. */
    Label label(ExpressionContext expression) {
        return program.symbolOf(expression).orElse(null) instanceof Label label ? label : null;
    }

    /** The Java value of a label: its field, or the wave's label of an {@code SLabel}. */
    String labelValue(Label label) {
        return label.sharing() == Sharing.SHARED ? "ctx.shared(" + structure.sharedLabel(label) + ").get()"
                : localLabel(label);
    }

    /**
     * The label and addressee of a label form's receiver: {@code l.a} (a named agent or a variable
     * holding one), {@code l.this} or {@code l} (the current agent, agent null); null if it is none.
     */
    record LabelForm(Label label, ExpressionContext agent) {
    }

    LabelForm labelForm(ExpressionContext receiver) {
        if (receiver instanceof MASLParser.LabelSelfContext self && label(self.expression()) != null) {
            return new LabelForm(label(self.expression()), null);
        }
        if (receiver instanceof MASLParser.FieldAccessContext access && label(access.expression()) != null) {
            return new LabelForm(label(access.expression()), access);
        }
        Label label = label(receiver);
        return label == null ? null : new LabelForm(label, null);
    }

    /** The Java of the agent a label form addresses. */
    String addressee(LabelForm form) {
        if (form.agent() == null) {
            return "self";
        }
        Symbol symbol = program.symbolOf(form.agent()).orElse(null);
        if (symbol instanceof AgentDecl agent) {
            return expressions.agent(agent);
        }
        if (symbol instanceof Variable variable) {
            return expressions.read(variable);
        }
        return unsupported.report(form.agent(), "this label addressee");
    }

    /**
     * A launch registered with a label (§10, contract §8.3): {@code l.a.m(…)}, and the value of
     * {@code l.x = a.m(…)} with {@code store} the Java consumer of the result (null for none). An
     * asynchronous primitive is launched and the instruction ends at once; a synchronous one is
     * invoked and awaited, registered as done. An addressee that may lack the primitive (§4) goes
     * through a helper that registers the call, or its {@code nop()}, itself.
     */
    String labelLaunch(Label label, ExpressionContext agent, String callee, String name,
            List<ExpressionContext> arguments, String store, ParserRuleContext where) {
        AgentType calleeType = labelCallee(agent, name, where);
        if (calleeType == null) {
            return unsupported.report(where, "a label invocation of a primitive the agent's own type lacks, inside an"
                    + " expression,");
        }
        AgentType receiverType = agent == null ? selfType.descriptor() : expressions.queries().descriptorOf(agent);
        Primitive primitive = calleeType.findPrimitive(name).orElseThrow();
        List<String> java = members.arguments(primitive, arguments);
        AgentCalls.Kind kind = primitive.synchronous() ? AgentCalls.Kind.INVOKE : AgentCalls.Kind.LAUNCH;
        Primitive countermeasure = primitive.synchronous() || primitive.countermeasure() == null ? null
                : calleeType.findPrimitive(primitive.countermeasure()).orElse(null);
        String calleeClass = calleeType.fullClassName();
        String receiverClass = AgentMemberWriter.receiverClass(receiverType, calleeType);
        AgentCalls calls = expressions.calls();
        String registered = calleeClass.equals(receiverClass)
                ? labelValue(label) + ".register(" + calls.call(kind, primitive, countermeasure, calleeClass, callee, java)
                        + (store == null ? ")" : ", " + store + ")")
                : calls.registered(kind, primitive, countermeasure, calleeClass, receiverClass, labelValue(label), callee,
                        java, store);
        if (!primitive.synchronous()) {
            return registered;
        }
        return expressions.awaited(registered, primitive, where);
    }

    /** Whether a statement is a label launch of an asynchronous primitive: zero duration (§5, §10). */
    boolean isAsynchronousLabelLaunch(ExpressionContext expression) {
        ExpressionContext call = expression instanceof MASLParser.AssignExprContext assignment ? assignment.value
                : expression;
        boolean labelForm = expression instanceof MASLParser.AssignExprContext assignment
                ? assignment.target instanceof MASLParser.FieldAccessContext access
                        && labelForm(access.expression()) != null
                : call instanceof MASLParser.MethodCallContext method && labelForm(method.expression()) != null;
        if (!labelForm) {
            return false;
        }
        String name = call instanceof MASLParser.MethodCallContext method ? method.identifier().getText()
                : call instanceof MASLParser.PrimaryExprContext primary
                        && primary.primary() instanceof MASLParser.SelfInvocationContext self
                        ? self.identifier().getText() : null;
        if (name == null) {
            return false;
        }
        ExpressionContext agent = expression instanceof MASLParser.AssignExprContext
                ? (call instanceof MASLParser.MethodCallContext method && !TreeQueries.isThis(method.expression())
                        ? method.expression() : null)
                : labelForm(((MASLParser.MethodCallContext) call).expression()).agent();
        AgentType calleeType = labelCallee(agent, name, call);
        return calleeType != null && !calleeType.findPrimitive(name).orElseThrow().synchronous();
    }

    /**
     * The type whose primitive {@code name} a label's invocation {@code where} of {@code agent}
     * (null for the current agent) calls, as {@link AgentMemberWriter#declaringType} finds it.
     */
    private AgentType labelCallee(ExpressionContext agent, String name, ParserRuleContext where) {
        var receiverType = agent == null ? selfType.descriptor() : expressions.queries().descriptorOf(agent);
        return members.declaringType(receiverType, agent, where, type -> type.findPrimitive(name).isPresent());
    }
}
