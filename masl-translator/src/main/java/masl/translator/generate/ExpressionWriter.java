package masl.translator.generate;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import masl.runtime.descriptor.Primitive;
import masl.translator.analysis.AgentDecl;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.Block;
import masl.translator.analysis.EntryRef;
import masl.translator.analysis.EventDecl;
import masl.translator.analysis.ImportedType;
import masl.translator.analysis.MaslType;
import masl.translator.analysis.Member;
import masl.translator.analysis.Sharing;
import masl.translator.analysis.Symbol;
import masl.translator.analysis.TypeRef;
import masl.translator.analysis.Variable;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * Translates MASL expressions (MASL §3) to Java for the program of one agent type: locals are
 * fields of the program object, shared variables go through {@code ctx.shared(…)} (atomic
 * read-modify-write, §7), primitives are called on {@code self}, entry members on
 * {@code ctx.entry(…)}, and the relaxed typing of §3 becomes conversions and value equality.
 */
final class ExpressionWriter {

    private static final List<String> LIST_MEMBERS = List.of("getList", "getActiveList", "getWaitingInList",
            "getWaitingOutList");

    private final AnalyzedProgram program;
    private final StaticStructure structure;
    private final ImportedType selfType;
    private final Unsupported unsupported;
    private final TreeQueries queries;
    private final AssignmentWriter assignments;
    /**
     * The program's fields: {@code block$name} for a local, {@code agent$name}, {@code tmp$1}, ....
     * MASL names may hold {@code $} ({@code a$b}'s local {@code c} and {@code a}'s local {@code b$c}),
     * so every field's name is taken here, distinct from all others.
     */
    private final JavaNames.Unique fields = new JavaNames.Unique("self");
    private final Map<Block, String> keepFlags = new java.util.HashMap<>();
    private final Map<Variable, String> locals = new java.util.LinkedHashMap<>();
    private final AgentCalls calls = new AgentCalls();
    /** The agents named in the program that it uses, with the program's field holding each. */
    private final Map<AgentDecl, String> agents = new java.util.LinkedHashMap<>();
    /** Suspension points met in the expressions written since they were last taken (contract §3.11). */
    private final List<Suspension> suspensions = new ArrayList<>();
    private final FutureVariables futures;
    /** The expression whose asynchronous invocation gives its future rather than its awaited value. */
    private ExpressionContext unawaited;
    private boolean usesDynamicMembers;
    private final TypeTests typeTests;
    private final AgentMemberWriter members;
    private final LabelWriter labels;
    /** Inside the function of an atomic update: the variable updated and the function's parameter. */
    private Variable updated;
    private String updatedParameter;

    ExpressionWriter(AnalyzedProgram program, StaticStructure structure, ImportedType selfType,
            Unsupported unsupported) {
        this.program = program;
        this.structure = structure;
        this.selfType = selfType;
        this.unsupported = unsupported;
        this.queries = new TreeQueries(program, selfType);
        this.typeTests = new TypeTests(program, selfType);
        this.assignments = new AssignmentWriter(program, structure, this, queries, unsupported);
        this.futures = new FutureVariables(program, queries);
        this.members = new AgentMemberWriter(program, selfType, unsupported, this);
        this.labels = new LabelWriter(program, structure, selfType, unsupported, this, members);
    }

    /**
     * A wait for a result inside an expression: {@code start} (null when the future is already
     * held) gives {@code future}, which the program awaits before evaluating the expression.
     */
    record Suspension(String start, String future, String what) {
    }

    /** Takes the suspension points of the expressions written since the last call, in evaluation order. */
    List<Suspension> takeSuspensions() {
        List<Suspension> taken = List.copyOf(suspensions);
        suspensions.clear();
        return taken;
    }

    /** Whether {@code tree} waits for a result: an external invocation, a read of a future (§3.11). */
    boolean suspends(org.antlr.v4.runtime.tree.ParseTree tree) {
        if (tree instanceof ExpressionContext expression && labels.isAsynchronousLabelLaunch(expression)) {
            // Launched and registered with the label, not waited for: only its arguments may wait.
            ExpressionContext call = expression instanceof MASLParser.AssignExprContext assignment ? assignment.value
                    : expression;
            MASLParser.ArgumentsContext arguments = call instanceof MASLParser.MethodCallContext method
                    ? method.arguments()
                    : ((MASLParser.SelfInvocationContext) ((MASLParser.PrimaryExprContext) call).primary()).arguments();
            return arguments(arguments).stream().anyMatch(argument -> queries.suspends(argument, futures));
        }
        return queries.suspends(tree, futures);
    }

    /** Whether a local holds the future of an asynchronous invocation (§9): reading it awaits it. */
    boolean holdsFuture(Variable variable) {
        return futures.contains(variable);
    }

    /** Writes {@code expression} leaving the asynchronous invocation it is, if it is one, unawaited. */
    String unawaited(ExpressionContext expression) {
        ExpressionContext outer = unawaited;
        unawaited = expression;
        try {
            return expr(expression);
        } finally {
            unawaited = outer;
        }
    }

    /** {@code value} stored into a local holding a future: its future, unawaited, or a completed one. */
    String future(MaslType type, ExpressionContext value) {
        if (futures.isLaunch(value)) {
            return unawaited(value);
        }
        return "CompletableFuture.completedFuture(" + convertedBoxed(type, value) + ")";
    }

    AgentCalls calls() {
        return calls;
    }

    /** The named agents the program uses: each is a field of the program, set from the population. */
    Map<AgentDecl, String> agents() {
        return agents;
    }

    /** The field of a local variable: {@code block$name}. */
    String local(Variable variable) {
        return locals.computeIfAbsent(variable, v -> fields.take(v.block().name() + "$" + v.name()));
    }

    /** The flag of a block whose locals a reelect keeps (contract §3.6): {@code keep$block}. */
    String keepFlag(Block block) {
        return keepFlags.computeIfAbsent(block, b -> fields.take("keep$" + b.name()));
    }

    /** A new field of the program, named {@code wanted} unless another field has that name. */
    String field(String wanted) {
        return fields.take(wanted);
    }

    /** The locals used so far, with their fields. */
    Map<Variable, String> locals() {
        return locals;
    }

    /** Whether members of Object-typed values were used: the program class then needs {@link DynamicMembers}. */
    boolean usesDynamicMembers() {
        return usesDynamicMembers;
    }

    /** Whether a type test on another agent was written: the program class then needs {@link TypeTests#helper()}. */
    boolean usesAgentTypeTests() {
        return typeTests.used();
    }

    ImportedType selfType() {
        return selfType;
    }

    TreeQueries queries() {
        return queries;
    }

    AssignmentWriter assignments() {
        return assignments;
    }

    // ------------------------------------------------------------------ conversions

    /** An entry test or a condition: numbers are true when non-zero (§3). */
    String condition(ExpressionContext expression) {
        if (queries.usesAbsentMember(expression)) {
            return "false";
        }
        if (queries.throwsChecked(expression)) {
            return unsupported.report(expression, "a Java call that may throw a checked exception, in a condition,");
        }
        return truth(expression);
    }

    private String truth(ExpressionContext expression) {
        MaslType type = program.typeOf(expression);
        String java = expr(expression);
        if (JavaTypes.isBoolean(type)) {
            return java;
        }
        if (JavaTypes.isNumeric(type)) {
            return "(" + java + ") != 0";
        }
        return "(boolean) (" + java + ")";
    }

    /** {@code expression} converted for a variable, parameter or attribute of type {@code target} (§3). */
    String converted(MaslType target, ExpressionContext expression) {
        return convert(target, program.typeOf(expression), expr(expression));
    }

    /**
     * {@code expression} converted for a shared variable of type {@code target}: its value is boxed
     * as the variable's own type, so a number of another type is cast first ({@code 10} for a {@code long}).
     */
    String convertedBoxed(MaslType target, ExpressionContext expression) {
        return exactly(target, program.typeOf(expression), converted(target, expression));
    }

    private static String exactly(MaslType target, MaslType source, String java) {
        Class<?> from = JavaTypes.unboxed(source);
        if (target instanceof MaslType.JavaPrimitive primitive && from != null && from != primitive.type()
                && !java.startsWith("(" + primitive.type().getName() + ")")) {
            return "(" + primitive.type().getName() + ") (" + java + ")";
        }
        return java;
    }

    private static String convert(MaslType target, MaslType source, String java) {
        if (MaslType.STRING.equals(target) && !MaslType.STRING.equals(source) && source != MaslType.NULL) {
            return "String.valueOf(" + java + ")";
        }
        if (target instanceof MaslType.JavaPrimitive primitive && JavaTypes.isPrimitive(source)) {
            Class<?> to = primitive.type();
            Class<?> from = ((MaslType.JavaPrimitive) source).type();
            boolean narrowing = (to == byte.class || to == short.class || to == char.class) && from != to;
            return narrowing ? "(" + to.getName() + ") (" + java + ")" : java;
        }
        if (MaslType.OBJECT.equals(source) && !MaslType.OBJECT.equals(target)) {
            return "(" + JavaTypes.name(target) + ") (" + java + ")";
        }
        if (target instanceof MaslType.AgentRef && source instanceof MaslType.AgentRef
                && !target.javaName().equals(source.javaName())) {
            return "(" + target.javaName() + ") (" + java + ")";
        }
        String anyAgents = ".toArray(new " + MaslType.ANY_AGENT.javaName() + "[0])";
        if (target instanceof MaslType.ArrayOf array && array.element() instanceof MaslType.AgentRef
                && java.endsWith(anyAgents)) {
            // An entry list assigned to an array of a common agent type: its elements are of that type (§6.7).
            return java.substring(0, java.length() - anyAgents.length()) + ".toArray(new "
                    + array.element().javaName() + "[0])";
        }
        return java;
    }

    /** A variable initialiser, array initialisers included. */
    String initializer(MaslType target, MASLParser.VariableInitializerContext initializer) {
        if (queries.usesAbsentMember(initializer)) {
            return JavaTypes.defaultValue(target);
        }
        if (queries.throwsChecked(initializer)) {
            return unsupported.report(initializer, "a Java call that may throw a checked exception, in an initialiser,");
        }
        if (initializer.expression() != null) {
            return convertedBoxed(target, initializer.expression());
        }
        return "new " + JavaTypes.name(target) + " " + arrayInitializer(target, initializer.arrayInitializer());
    }

    private String arrayInitializer(MaslType target, MASLParser.ArrayInitializerContext initializer) {
        MaslType element = target instanceof MaslType.ArrayOf array ? array.element() : MaslType.OBJECT;
        List<String> elements = new ArrayList<>();
        for (MASLParser.VariableInitializerContext item : initializer.variableInitializer()) {
            elements.add(item.expression() != null ? converted(element, item.expression())
                    : arrayInitializer(element, item.arrayInitializer()));
        }
        return "{" + String.join(", ", elements) + "}";
    }

    // ------------------------------------------------------------------ expressions

    String expr(ExpressionContext expression) {
        if (expression instanceof MASLParser.PrimaryExprContext primary) {
            return primary(primary);
        } else if (expression instanceof MASLParser.FieldAccessContext access) {
            return fieldAccess(access);
        } else if (expression instanceof MASLParser.MethodCallContext call) {
            return methodCall(call);
        } else if (expression instanceof MASLParser.ArrayAccessContext access) {
            return expr(access.expression(0)) + "[" + expr(access.index) + "]";
        } else if (expression instanceof MASLParser.PostfixExprContext postfix) {
            return assignments.increment(postfix.expression(), postfix.op.getText(), false, false);
        } else if (expression instanceof MASLParser.PrefixExprContext prefix) {
            String operator = prefix.op.getText();
            if (operator.equals("++") || operator.equals("--")) {
                return assignments.increment(prefix.expression(), operator, true, false);
            }
            return unary(operator, expr(prefix.expression()));
        } else if (expression instanceof MASLParser.NotExprContext not) {
            return not.op.getText().equals("!") ? "!(" + truth(not.expression()) + ")"
                    : unary("~", expr(not.expression()));
        } else if (expression instanceof MASLParser.CastExprContext cast) {
            return "(" + JavaTypes.name(program.typeOf(cast)) + ") " + expr(cast.expression());
        } else if (expression instanceof MASLParser.BinaryExprContext binary) {
            return binary(binary);
        } else if (expression instanceof MASLParser.ShiftExprContext shift) {
            return expr(shift.left) + " " + shift.shiftOperator().getText() + " " + expr(shift.right);
        } else if (expression instanceof MASLParser.ConditionalExprContext conditional) {
            if (suspends(conditional.whenTrue) || suspends(conditional.whenFalse)) {
                return unsupported.report(conditional, "waiting for a result (an invocation of another agent, a future) in a"
                        + " branch of ?:,");
            }
            return truth(conditional.condition) + " ? " + expr(conditional.whenTrue) + " : "
                    + expr(conditional.whenFalse);
        } else if (expression instanceof MASLParser.AssignExprContext assignment) {
            return assignments.assignment(assignment, false);
        } else if (expression instanceof MASLParser.InstanceofExprContext test) {
            if (typeTests.isAgentTypeTest(test)) {
                return typeTests.write(test, expr(test.expression()));
            }
            // Type arguments are erased, as the analysis does.
            return expr(test.expression()) + " instanceof " + JavaTypes.name(program.typeOf(test.javaType()));
        }
        return unsupported.report(expression, "this expression");
    }

    private static String unary(String operator, String operand) {
        return operand.startsWith(operator.substring(0, 1)) ? operator + " " + operand : operator + operand;
    }

    private String binary(MASLParser.BinaryExprContext binary) {
        String operator = binary.op.getText();
        if (operator.equals("&&") || operator.equals("||")) {
            if (suspends(binary.right)) {
                return unsupported.report(binary.right, "waiting for a result (an invocation of another agent, a future) in the"
                        + " right operand of " + operator + ",");
            }
            return truth(binary.left) + " " + operator + " " + truth(binary.right);
        }
        if (operator.equals("==") || operator.equals("!=") || operator.equals("<>")) {
            boolean equal = operator.equals("==");
            MaslType left = program.typeOf(binary.left);
            MaslType right = program.typeOf(binary.right);
            boolean javaEquality = JavaTypes.isPrimitive(left) && (JavaTypes.unboxed(right) != null)
                    || JavaTypes.isPrimitive(right) && (JavaTypes.unboxed(left) != null);
            if (!javaEquality) {
                // Value equality on non-primitive operands (§3): getLockPolicy() == "free" holds.
                return (equal ? "" : "!") + "Objects.equals(" + expr(binary.left) + ", " + expr(binary.right) + ")";
            }
            return expr(binary.left) + (equal ? " == " : " != ") + expr(binary.right);
        }
        return expr(binary.left) + " " + operator + " " + expr(binary.right);
    }

    private String primary(MASLParser.PrimaryExprContext expression) {
        MASLParser.PrimaryContext primary = expression.primary();
        if (primary instanceof MASLParser.ParenExprContext paren) {
            return "(" + expr(paren.expression()) + ")";
        } else if (primary instanceof MASLParser.LiteralExprContext literal) {
            return JavaText.literal(literal.literal());
        } else if (primary instanceof MASLParser.ThisExprContext) {
            return "self";
        } else if (primary instanceof MASLParser.SelfInvocationContext call) {
            return members.primitiveCall(null, call.identifier().getText(), arguments(call.arguments()), expression);
        } else if (primary instanceof MASLParser.SelfAttributeContext attribute) {
            return members.attributeRead(null, attribute.identifier().getText(), expression);
        } else if (primary instanceof MASLParser.NameExprContext) {
            return name(expression);
        } else if (primary instanceof MASLParser.NewExprContext creation) {
            return creation(creation.creator(), expression);
        } else if (primary instanceof MASLParser.PrimitiveClassLiteralContext literal) {
            return literal.getText();
        } else if (primary instanceof MASLParser.PlainCallContext call) {
            // isFinished(l), the one call without a receiver (MASL 10).
            return labels.labelValue(labels.label(arguments(call.arguments()).get(0))) + ".isFinished()";
        } else if (primary instanceof MASLParser.GetAcceptStateExprContext state) {
            return state.agent == null ? "ctx.getAcceptState()" : "ctx.getAcceptState(" + expr(state.agent) + ")";
        } else if (primary instanceof MASLParser.GetMessageExprContext message) {
            return "ctx.messageOf(" + event(message.event) + ")";
        }
        return unsupported.report(expression, "this expression");
    }

    private String name(MASLParser.PrimaryExprContext expression) {
        Symbol symbol = program.symbolOf(expression).orElse(null);
        if (symbol instanceof Variable variable) {
            return read(variable);
        }
        if (symbol instanceof TypeRef type) {
            return JavaTypes.name(type.type());
        }
        if (symbol instanceof AgentDecl agent) {
            return agent(agent);
        }
        if (symbol instanceof Member member && member.kind() == Member.Kind.ATTRIBUTE) {
            return members.attributeRead(null, member.name(), expression);
        }
        return unsupported.report(expression, "this name");
    }

    /** Generates {@code body} as the function of an atomic update of {@code variable}: its reads are the parameter. */
    String whileUpdating(Variable variable, String parameter, java.util.function.Supplier<String> body) {
        Variable outer = updated;
        String outerParameter = updatedParameter;
        updated = variable;
        updatedParameter = parameter;
        try {
            return body.get();
        } finally {
            updated = outer;
            updatedParameter = outerParameter;
        }
    }

    /** The expression of the event an identifier names (as the analysis bound it). */
    String event(MASLParser.IdentifierContext name) {
        if (program.symbolOf(name).orElse(null) instanceof EventDecl event) {
            return structure.event(event);
        }
        return unsupported.report(name, "this event");
    }

    /** The value of a variable. */
    String read(Variable variable) {
        if (variable == updated) {
            return updatedParameter;
        }
        if (variable.sharing() == Sharing.SHARED) {
            return "ctx.shared(" + structure.shared(variable) + ").get()";
        }
        if (futures.contains(variable)) {
            // Holding a future does not block; reading it waits for the result (MASL 9).
            suspensions.add(new Suspension(null, local(variable), "the result " + variable.name() + " holds"));
            return local(variable) + ".join()";
        }
        return local(variable);
    }

    private String creation(MASLParser.CreatorContext creator, ExpressionContext expression) {
        MaslType created = program.typeOf(expression);
        if (creator instanceof MASLParser.ObjectCreatorContext object) {
            return "new " + JavaTypes.name(created) + "(" + String.join(", ", all(arguments(object.arguments())))
                    + ")";
        }
        if (creator instanceof MASLParser.ArrayCreatorContext array) {
            StringBuilder text = new StringBuilder("new ").append(JavaTypes.name(innermost(created)));
            for (ExpressionContext size : array.expression()) {
                text.append('[').append(expr(size)).append(']');
            }
            if (array.dims() != null) {
                text.append("[]".repeat(array.dims().LBRACK().size()));
            }
            return text.toString();
        }
        MASLParser.ArrayLiteralCreatorContext literal = (MASLParser.ArrayLiteralCreatorContext) creator;
        return "new " + JavaTypes.name(created) + " " + arrayInitializer(created, literal.arrayInitializer());
    }

    private static MaslType innermost(MaslType type) {
        return type instanceof MaslType.ArrayOf array ? innermost(array.element()) : type;
    }

    private String fieldAccess(MASLParser.FieldAccessContext access) {
        Symbol symbol = program.symbolOf(access).orElse(null);
        String name = access.identifier().getText();
        if (symbol instanceof TypeRef type) {
            return JavaTypes.name(type.type());
        }
        if (!(symbol instanceof Member member)) {
            return unsupported.report(access, "this member access");
        }
        return switch (member.kind()) {
            case ENTRY_MEMBER -> entry(access.expression()) + "." + name + "()";
            case ATTRIBUTE -> members.attributeRead(access.expression(), name, access);
            case JAVA_FIELD -> receiver(access.expression()) + "." + name;
            case DYNAMIC -> dynamicField(access.expression(), name);
            default -> unsupported.report(access, "this member access");
        };
    }

    private String methodCall(MASLParser.MethodCallContext call) {
        Symbol symbol = program.symbolOf(call).orElse(null);
        String name = call.identifier().getText();
        List<ExpressionContext> arguments = arguments(call.arguments());
        LabelWriter.LabelForm form = labels.labelForm(call.expression());
        if (form != null && !(symbol instanceof Member labelMember && labelMember.kind() == Member.Kind.LABEL_MEMBER)) {
            return labels.labelLaunch(form.label(), form.agent(), labels.addressee(form), name, arguments, null, call);
        }
        if (!(symbol instanceof Member member)) {
            return unsupported.report(call, "this call");
        }
        return switch (member.kind()) {
            case PRIMITIVE -> members.primitiveCall(call.expression(), name, arguments, call);
            case ENTRY_MEMBER -> entryCall(call.expression(), name, arguments);
            case JAVA_METHOD -> receiver(call.expression()) + "." + name + "(" + String.join(", ", all(arguments))
                    + ")";
            case LABEL_MEMBER -> labels.labelValue(labels.label(call.expression())) + "." + name + "()";
            case DYNAMIC -> dynamicCall(call.expression(), name, arguments);
            default -> unsupported.report(call, "this call");
        };
    }

    private String dynamicField(ExpressionContext receiver, String name) {
        usesDynamicMembers = true;
        return DynamicMembers.field(expr(receiver), name);
    }

    private String dynamicCall(ExpressionContext receiver, String name, List<ExpressionContext> arguments) {
        usesDynamicMembers = true;
        return DynamicMembers.call(expr(receiver), name, all(arguments));
    }

    private String receiver(ExpressionContext expression) {
        Symbol symbol = program.symbolOf(expression).orElse(null);
        if (symbol instanceof TypeRef type) {
            return JavaTypes.name(type.type());
        }
        return expr(expression);
    }

    private String entry(ExpressionContext receiver) {
        if (program.symbolOf(receiver).orElse(null) instanceof EntryRef entry && entry.block() != null) {
            return "ctx.entry(" + structure.block(entry.block()) + ")";
        }
        return unsupported.report(receiver, "this entry");
    }

    private String entryCall(ExpressionContext receiver, String name, List<ExpressionContext> arguments) {
        String call = entry(receiver) + "." + name + "(" + String.join(", ", all(arguments)) + ")";
        if (LIST_MEMBERS.contains(name)) {
            // Entry lists hold the agents' implementations; MASL sees an array of agents (§6.7).
            return call + ".toArray(new " + MaslType.ANY_AGENT.javaName() + "[0])";
        }
        return call;
    }

    /** The field holding a named agent's implementation: {@code agent$b}. */
    String agent(AgentDecl agent) {
        return agents.computeIfAbsent(agent, a -> fields.take("agent$" + a.name()));
    }

    /** A future started before the statement, awaited, and read where the call stood. */
    String awaited(String start, Primitive primitive, ParserRuleContext call) {
        String future = assignments.temporary(AgentCalls.futureType(primitive));
        suspensions.add(new Suspension(future + " = " + start + ";", future, "the result of " + JavaText.snippet(call)));
        return future + ".join()";
    }

    /** Whether {@code call} is the asynchronous invocation whose future, not its value, is wanted. */
    boolean isUnawaited(ParserRuleContext call) {
        return call == unawaited;
    }

    LabelWriter labels() {
        return labels;
    }

    AgentMemberWriter members() {
        return members;
    }

    // ------------------------------------------------------------------ helpers

    static List<ExpressionContext> arguments(MASLParser.ArgumentsContext arguments) {
        return arguments.expressionList() == null ? List.of() : arguments.expressionList().expression();
    }

    private List<String> all(List<ExpressionContext> expressions) {
        List<String> java = new ArrayList<>();
        for (ExpressionContext expression : expressions) {
            java.add(expr(expression));
        }
        return java;
    }
}
