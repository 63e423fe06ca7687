package masl.translator.generate;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.MaslType;
import masl.translator.analysis.Member;
import masl.translator.analysis.Sharing;
import masl.translator.analysis.Symbol;
import masl.translator.analysis.Variable;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * Translates assignments, increments and decrements (MASL §7): locals are fields written directly;
 * a shared variable is written through its wave's {@code SharedVariable}, every read-modify-write as
 * one atomic update; an element of an array a shared variable holds as {@link SharedElementWriter} says.
 */
final class AssignmentWriter {

    /** A Java operand that needs no parentheses after an operator: a name, a number, a plain string. */
    private static final Pattern SIMPLE_OPERAND = Pattern.compile("[\\w$.]+|\"[^\"\\\\]*\"");

    private final AnalyzedProgram program;
    private final StaticStructure structure;
    private final ExpressionWriter expressions;
    private final TreeQueries queries;
    private final Unsupported unsupported;
    private final SharedElementWriter elements;
    /** Temporaries of split expressions, field name to Java type. */
    private final Map<String, String> temporaries = new LinkedHashMap<>();
    /** Statements to run before the one being translated: values hoisted out of atomic updates. */
    private final List<String> hoisted = new ArrayList<>();

    AssignmentWriter(AnalyzedProgram program, StaticStructure structure, ExpressionWriter expressions,
            TreeQueries queries, Unsupported unsupported) {
        this.program = program;
        this.structure = structure;
        this.expressions = expressions;
        this.queries = queries;
        this.unsupported = unsupported;
        this.elements = new SharedElementWriter(program, structure, expressions, this);
    }

    /** The temporaries used so far: field name to Java type. */
    Map<String, String> temporaries() {
        return temporaries;
    }

    /** Takes the statements that must run before the statement just translated, in order. */
    List<String> takeHoisted() {
        List<String> taken = List.copyOf(hoisted);
        hoisted.clear();
        return taken;
    }

    /**
     * An assignment. A shared variable is written atomically: {@code set} when the value does not
     * read it, otherwise {@code update} with the read-modify-write as a function of the old value.
     */
    String assignment(MASLParser.AssignExprContext assignment, boolean isStatement) {
        String operator = assignment.op.getText();
        ExpressionContext target = assignment.target;
        ExpressionContext value = assignment.value;
        MaslType type = program.typeOf(target);
        Symbol symbol = program.symbolOf(target).orElse(null);
        if (target instanceof MASLParser.FieldAccessContext access
                && expressions.labels().labelForm(access.expression()) != null) {
            return labelAssignment(access, symbol, value);
        }
        Variable array = elements.sharedArray(target);
        if (array != null) {
            String written = operator.equals("=") ? expressions.converted(type, value) : expressions.expr(value);
            return elements.assignment(array, target, operator, written, isStatement);
        }
        if (symbol instanceof Variable variable) {
            if (!maySelfWrite(variable)) {
                return ignoredWrite(assignment, isStatement, variable);
            }
            if (expressions.holdsFuture(variable)) {
                return futureAssignment(assignment, variable);
            }
            if (variable.sharing() == Sharing.LOCAL) {
                return expressions.local(variable) + " " + operator + " "
                        + (operator.equals("=") ? expressions.converted(type, value) : expressions.expr(value));
            }
            String shared = "ctx.shared(" + structure.shared(variable) + ")";
            if (operator.equals("=") && isStatement && !queries.mentions(value, variable)) {
                return shared + ".set(" + expressions.convertedBoxed(type, value) + ")";
            }
            String parameter = lambdaParameter(variable);
            String binary = operator.substring(0, operator.length() - 1);
            if (isStatement && !operator.equals("=") && !queries.mentions(value, variable) && !isSimple(value)) {
                // Only what reads the variable runs under its monitor (x += .sense() calls the primitive first).
                String temporary = hoist(value);
                return shared + ".update(" + parameter + " -> "
                        + compound(type, parameter, binary, temporary, program.typeOf(value)) + ")";
            }
            String function = expressions.whileUpdating(variable, parameter, () -> operator.equals("=") ? expressions.convertedBoxed(type, value)
                    : compound(type, parameter, binary, expressions.expr(value), program.typeOf(value)));
            return shared + ".update(" + parameter + " -> " + function + ")";
        }
        if (symbol instanceof Member member && member.kind() == Member.Kind.ATTRIBUTE) {
            return attributeUpdate(target, member, operator, value, isStatement);
        }
        if (symbol instanceof Member member && member.kind() == Member.Kind.DYNAMIC) {
            return unsupported.report(target, "an assignment to a field of an Object-typed value");
        }
        String left = expressions.expr(target);
        return left + " " + operator + " " + (operator.equals("=") ? expressions.converted(type, value) : expressions.expr(value));
    }

    /** A new temporary field of Java type {@code javaType}. */
    String temporary(String javaType) {
        String temporary = expressions.field("tmp$" + (temporaries.size() + 1));
        temporaries.put(temporary, javaType);
        return temporary;
    }

    /**
     * {@code l.x = a.m(…)}, {@code l.a.x = …}, {@code l.this.x = …} (§10): the invocation is
     * registered with the label, which stores its result in the variable or attribute when it comes.
     */
    private String labelAssignment(MASLParser.FieldAccessContext target, Symbol symbol, ExpressionContext value) {
        ExpressionContext agent = null;
        String name;
        List<ExpressionContext> arguments;
        if (value instanceof MASLParser.MethodCallContext call) {
            agent = TreeQueries.isThis(call.expression()) ? null : call.expression();
            name = call.identifier().getText();
            arguments = ExpressionWriter.arguments(call.arguments());
        } else {
            MASLParser.SelfInvocationContext self = (MASLParser.SelfInvocationContext)
                    ((MASLParser.PrimaryExprContext) value).primary();
            name = self.identifier().getText();
            arguments = ExpressionWriter.arguments(self.arguments());
        }
        String callee = agent == null ? "self" : expressions.expr(agent);
        String store;
        LabelWriter.LabelForm form = expressions.labels().labelForm(target.expression());
        boolean toVariable = expressions.labels().label(target.expression()) != null;
        if (toVariable && symbol instanceof Variable variable) {
            String converted = MaslType.STRING.equals(variable.type()) ? "String.valueOf(value)" : "value";
            store = variable.sharing() == Sharing.SHARED
                    ? "value -> ctx.shared(" + structure.shared(variable) + ").set(" + converted + ")"
                    : "value -> " + expressions.local(variable) + " = " + converted;
        } else {
            store = expressions.members().attributeStore(form.agent(), expressions.labels().addressee(form), target.identifier().getText(),
                    target);
        }
        return expressions.labels().labelLaunch(form.label(), agent, callee, name, arguments, store, value);
    }

    /**
     * An assignment to a local holding a future (MASL 9): an asynchronous invocation stores its
     * future without waiting; any other value is stored as a completed future.
     */
    private String futureAssignment(MASLParser.AssignExprContext assignment, Variable variable) {
        if (!assignment.op.getText().equals("=")) {
            return unsupported.report(assignment, "a compound assignment to a variable holding a future");
        }
        return expressions.local(variable) + " = " + expressions.future(variable.type(), assignment.value);
    }

    /**
     * An assignment to an attribute (§8.4), of the current agent or another: a write through the
     * runtime, filtered by permeability; {@code x op= e} and {@code x++} read it first.
     * {@code value} is null for an increment ({@code +=} / {@code -=} of one).
     */
    private String attributeUpdate(ExpressionContext target, Member member, String operator, ExpressionContext value,
            boolean isStatement) {
        if (!isStatement) {
            return unsupported.report(target, "an assignment to an attribute inside an expression");
        }
        ExpressionContext owner = target instanceof MASLParser.FieldAccessContext access ? access.expression() : null;
        MaslType type = program.typeOf(target);
        String written;
        if (operator.equals("=")) {
            written = expressions.converted(type, value);
        } else {
            String current = expressions.expr(target);
            String operand = value == null ? "1" : expressions.expr(value);
            MaslType operandType = value == null ? MaslType.INT : program.typeOf(value);
            written = compound(type, current, operator.substring(0, operator.length() - 1), operand, operandType);
        }
        return expressions.members().attributeWrite(owner, member.name(), written, target);
    }

    /** Evaluates {@code value} into a new temporary, before the statement; returns the temporary. */
    private String hoist(ExpressionContext value) {
        String temporary = temporary(JavaTypes.name(program.typeOf(value)));
        hoisted.add(temporary + " = " + expressions.expr(value) + ";");
        return temporary;
    }

    /** A literal or a name: nothing gained by evaluating it before an atomic update. */
    private static boolean isSimple(ExpressionContext value) {
        return value instanceof MASLParser.PrimaryExprContext primary
                && (primary.primary() instanceof MASLParser.LiteralExprContext
                || primary.primary() instanceof MASLParser.NameExprContext);
    }

    private String compound(MaslType type, String parameter, String operator, String value, MaslType valueType) {
        boolean simple = SIMPLE_OPERAND.matcher(value).matches();
        String java = parameter + " " + operator + " " + (simple ? value : "(" + value + ")");
        Class<?> target = JavaTypes.unboxed(type);
        Class<?> source = JavaTypes.unboxed(valueType);
        if (target == null || target == boolean.class || operator.startsWith("<") || operator.startsWith(">")) {
            return needsCast(target) ? "(" + target.getName() + ") (" + java + ")" : java;
        }
        boolean widens = source != null && JavaTypes.rank(source) > JavaTypes.rank(target);
        return needsCast(target) || widens ? "(" + target.getName() + ") (" + java + ")" : java;
    }

    private static boolean needsCast(Class<?> type) {
        return type == byte.class || type == short.class || type == char.class;
    }

    /** {@code x++}, {@code --x}, …; on a shared variable an atomic update returning the old or new value. */
    String increment(ExpressionContext target, String operator, boolean prefix, boolean isStatement) {
        Variable array = elements.sharedArray(target);
        if (array != null) {
            return elements.increment(array, target, operator, prefix, isStatement);
        }
        Symbol symbol = program.symbolOf(target).orElse(null);
        if (symbol instanceof Variable variable) {
            if (!maySelfWrite(variable)) {
                return ignoredWrite(target, isStatement, variable);
            }
            if (variable.sharing() == Sharing.SHARED) {
                String parameter = lambdaParameter(variable);
                Class<?> type = JavaTypes.unboxed(variable.type());
                String step = parameter + (operator.equals("++") ? " + 1" : " - 1");
                String function = needsCast(type) ? "(" + type.getName() + ") (" + step + ")" : step;
                return "ctx.shared(" + structure.shared(variable) + ")."
                        + (prefix ? "update(" : "getAndUpdate(") + parameter + " -> " + function + ")";
            }
        }
        if (symbol instanceof Member member && member.kind() == Member.Kind.DYNAMIC) {
            return unsupported.report(target, "an assignment to a field of an Object-typed value");
        }
        if (symbol instanceof Member member && member.kind() == Member.Kind.ATTRIBUTE) {
            return attributeUpdate(target, member, operator.substring(0, 1) + "=", null, isStatement);
        }
        if (symbol instanceof Variable variable && expressions.holdsFuture(variable)) {
            return unsupported.report(target, "an increment of a variable holding a future");
        }
        String operand = expressions.expr(target);
        return prefix ? operator + operand : operand + operator;
    }

    private boolean maySelfWrite(Variable variable) {
        return variable.limitedTo() == null || queries.selfType().isSubtypeOf(variable.limitedTo());
    }

    /**
     * A write to a variable {@code limited} to a type this agent is not of: ignored, and the writer
     * perceives {@code forbidden_access} with the variable's name as message (MASL 7, 8).
     */
    private String ignoredWrite(ParserRuleContext where, boolean isStatement, Variable variable) {
        if (isStatement) {
            return "ctx.emit(Event.FORBIDDEN_ACCESS, " + JavaText.quote(variable.name()) + ")";
        }
        return unsupported.report(where, "a write to a limited variable inside an expression");
    }

    private static String lambdaParameter(Variable variable) {
        String name = JavaNames.identifier(variable.name());
        return name.equals("ctx") || name.equals("self") ? name + "_" : name;
    }
}
