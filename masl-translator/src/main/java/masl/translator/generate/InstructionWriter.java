package masl.translator.generate;

import java.util.List;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import masl.grammar.MASLParser.StatementContext;
import masl.runtime.descriptor.Primitive;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.MaslType;
import masl.translator.analysis.Member;
import masl.translator.analysis.TypeRef;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * Translates instructions (expression statements, MASL §5): the Java of the statement, then the
 * step boundary unless it takes no time; {@code sleep} as a timed suspension; a statement using a
 * member its agent's type lacks as a {@code nop()} (§4).
 */
final class InstructionWriter {

    private final AnalyzedProgram program;
    private final CaseWriter cases;
    private final ExpressionWriter expressions;
    private final TreeQueries queries;
    private final AssignmentWriter assignments;
    private final String file;
    /** Whether the statements being written are a reaction's: they run in one go, with no step boundary. */
    private boolean inReaction;

    InstructionWriter(AnalyzedProgram program, CaseWriter cases, ExpressionWriter expressions, String file) {
        this.program = program;
        this.cases = cases;
        this.expressions = expressions;
        this.queries = expressions.queries();
        this.assignments = expressions.assignments();
        this.file = file;
    }

    void inReaction(boolean reaction) {
        inReaction = reaction;
    }

    boolean isInReaction() {
        return inReaction;
    }

    /** {@code emit e;} or {@code emitWithMessage(e, message);}: an instruction (MASL 8). */
    void emit(ParserRuleContext statement, MASLParser.IdentifierContext event, ExpressionContext message) {
        cases.note(at(statement) + ": " + JavaText.snippet(statement));
        String constant = expressions.event(event);
        if (message != null && queries.usesAbsentMember(message)) {
            nop();
        } else if (message == null) {
            cases.line("ctx.emit(" + constant + ");");
        } else {
            writeGuarded(message, "ctx.emit(" + constant + ", " + expressions.converted(MaslType.STRING, message)
                    + ");");
        }
        stepBoundary();
    }

    /** The step boundary after an instruction (MASL 5); none inside a reaction (MASL 8). */
    private void stepBoundary() {
        if (!inReaction) {
            cases.suspending("ctx.stepBoundary()", cases.point());
        }
    }

    private String at(ParserRuleContext tree) {
        return file + ":" + tree.getStart().getLine();
    }

    /** An expression statement: an instruction, followed by the step boundary unless it takes no time. */
    void write(MASLParser.ExpressionStmtContext statement) {
        ExpressionContext expression = statement.expression();
        cases.note(at(statement) + ": " + JavaText.snippet(statement));
        if (queries.usesAbsentMember(expression)) {
            nop();
        } else if (isSleep(expression)) {
            ExpressionContext duration = ExpressionWriter.arguments(sleepArguments(expression)).get(0);
            cases.suspending("ctx.sleep(" + expressions.expr(duration) + ")", cases.point());
            if (!inReaction) {
                cases.note(at(statement) + ": the step boundary after the sleep");
            }
        } else {
            writeGuarded(expression, statementJava(expression) + ";");
        }
        if (!isZeroDuration(expression)) {
            stepBoundary();
        }
    }

    private String statementJava(ExpressionContext expression) {
        if (expression instanceof MASLParser.AssignExprContext assignment) {
            return assignments.assignment(assignment, true);
        }
        if (expression instanceof MASLParser.PostfixExprContext postfix) {
            return assignments.increment(postfix.expression(), postfix.op.getText(), false, true);
        }
        if (expression instanceof MASLParser.PrefixExprContext prefix
                && (prefix.op.getText().equals("++") || prefix.op.getText().equals("--"))) {
            return assignments.increment(prefix.expression(), prefix.op.getText(), true, true);
        }
        // A call as a statement: an asynchronous primitive is launched and not waited for (MASL 9).
        return expressions.unawaited(expression);
    }

    /**
     * Waits for the results that the condition, test or initialiser just written reads (contract
     * §3.11), then, as an external invocation is an instruction, the step boundary (§8.1). Returns
     * whether it waited (and so stepped).
     */
    boolean awaitResults(ParserRuleContext statement) {
        List<ExpressionWriter.Suspension> waits = expressions.takeSuspensions();
        for (ExpressionWriter.Suspension wait : waits) {
            if (wait.start() != null) {
                cases.line(wait.start());
            }
            awaitResult(wait, statement);
        }
        if (!waits.isEmpty()) {
            stepBoundary();
            cases.note(at(statement) + ": " + JavaText.snippet(statement) + ", with the results it waited for");
        }
        return !waits.isEmpty();
    }

    /** The step boundary after {@code instruction}, written elsewhere (an initialiser calling a primitive). */
    void stepAfter(ParserRuleContext instruction) {
        stepBoundary();
        if (!inReaction) {
            cases.note(at(instruction) + ": after " + JavaText.snippet(instruction));
        }
    }

    /** {@code ctx.await(future)}: the program continues in a case named after what it waited for. */
    private void awaitResult(ExpressionWriter.Suspension wait, ParserRuleContext statement) {
        cases.suspending("ctx.await(" + wait.future() + ")", cases.point());
        cases.note(at(statement) + ": " + wait.what());
    }

    /** A statement using a member this agent's type lacks: a {@code nop()}, which takes its instruction (MASL 4). */
    private void nop() {
        cases.comment("a nop() for " + expressions.selfType().name()
                + ": its type lacks a member this statement uses (MASL 4)");
    }

    /** {@code setAcceptState(s);} (MASL 11): an instruction. */
    void setAcceptState(MASLParser.SetAcceptStateStmtContext statement) {
        cases.note(at(statement) + ": " + JavaText.snippet(statement));
        if (queries.usesAbsentMember(statement)) {
            nop();
        } else {
            writeGuarded(statement.expression(), "ctx.setAcceptState("
                    + expressions.converted(MaslType.STRING, statement.expression()) + ");");
        }
        stepBoundary();
    }

    /**
     * {@code wait(s);} / {@code wait(s, ms);} (MASL 11): the agent is attentive until an invocation
     * the state allows has run, or the time is over; then the instruction's step boundary.
     */
    void waitFor(MASLParser.WaitStmtContext statement) {
        cases.note(at(statement) + ": " + JavaText.snippet(statement));
        if (queries.usesAbsentMember(statement)) {
            nop();
            stepBoundary();
            return;
        }
        String state = expressions.converted(MaslType.STRING, statement.state);
        String timeout = statement.timeout == null ? "" : ", " + expressions.expr(statement.timeout);
        for (ExpressionWriter.Suspension wait : expressions.takeSuspensions()) {
            if (wait.start() != null) {
                cases.line(wait.start());
            }
            awaitResult(wait, statement);
        }
        cases.suspending("ctx.waitFor(" + state + timeout + ")", cases.point());
        stepBoundary();
    }

    /**
     * A statement, preceded by the values hoisted out of it; wrapped in {@code try} when it calls
     * code that may throw: the exception raises {@code uncaught_exception} (MASL 8, 9).
     */
    private void writeGuarded(ExpressionContext expression, String java) {
        List<ExpressionWriter.Suspension> waits = expressions.takeSuspensions();
        List<String> before = assignments.takeHoisted();
        boolean guarded = queries.mayThrow(expression);
        CaseWriter.Point skipped = cases.point();
        boolean skips = false;
        for (ExpressionWriter.Suspension wait : waits) {
            if (wait.start() != null && guarded) {
                // Arguments evaluated before the call may throw: the rest of the statement is skipped.
                cases.open("try {");
                cases.line(wait.start());
                cases.reopen("} catch (Exception thrown) {");
                cases.line("ctx.uncaughtException(thrown); // the statement's call threw: uncaught_exception (MASL 8)");
                cases.jump(skipped);
                cases.close("}");
                skips = true;
            } else if (wait.start() != null) {
                cases.line(wait.start());
            }
            awaitResult(wait, expression);
        }
        if (!guarded) {
            before.forEach(cases::line);
            cases.line(java);
            return;
        }
        cases.open("try {");
        before.forEach(cases::line);
        cases.line(java);
        cases.reopen("} catch (Exception thrown) {");
        cases.line("ctx.uncaughtException(thrown); // the statement's call threw: uncaught_exception (MASL 8)");
        cases.close("}");
        if (skips) {
            cases.place(skipped, null);
        }
    }

    /** {@code .sleep(ms)} (when the type keeps Default's) and {@code Thread.sleep(ms)}: a timed suspension. */
    private boolean isSleep(ExpressionContext expression) {
        MASLParser.ArgumentsContext arguments = sleepArguments(expression);
        return arguments != null && ExpressionWriter.arguments(arguments).size() == 1;
    }

    private MASLParser.ArgumentsContext sleepArguments(ExpressionContext expression) {
        if (expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.SelfInvocationContext call
                && call.identifier().getText().equals("sleep") && !overridesSleep()) {
            return call.arguments();
        }
        if (expression instanceof MASLParser.MethodCallContext call && call.identifier().getText().equals("sleep")) {
            if (program.symbolOf(call.expression()).orElse(null) instanceof TypeRef type
                    && type.type().javaName().equals("java.lang.Thread")) {
                return call.arguments();
            }
            if (call.expression() instanceof MASLParser.PrimaryExprContext receiver
                    && receiver.primary() instanceof MASLParser.ThisExprContext && !overridesSleep()) {
                return call.arguments();
            }
        }
        return null;
    }

    /** Whether a type below the root redeclares {@code sleep}: then it is called like any primitive. */
    private boolean overridesSleep() {
        for (var type = expressions.selfType().descriptor(); type != null && type.supertype() != null;
                type = type.supertype()) {
            if (type.declaredPrimitives().stream().anyMatch(p -> p.name().equals("sleep"))) {
                return true;
            }
        }
        return false;
    }

    /** Entry members and accessor primitives take no time: no step boundary after them (MASL 5). */
    private boolean isZeroDuration(ExpressionContext expression) {
        if (expressions.labels().isAsynchronousLabelLaunch(expression) && !expressions.suspends(expression)) {
            return true;
        }
        if (expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.PlainCallContext) {
            return true;
        }
        Member member = program.symbolOf(expression).orElse(null) instanceof Member m ? m : null;
        if (member == null) {
            return false;
        }
        if (member.kind() == Member.Kind.ENTRY_MEMBER || member.kind() == Member.Kind.LABEL_MEMBER) {
            return true;
        }
        if (member.kind() == Member.Kind.PRIMITIVE && TreeQueries.isInternalCall(expression)) {
            // Only an internal accessor call: an external invocation is always an instruction (contract §8.1).
            Primitive primitive = expressions.selfType().descriptor().findPrimitive(member.name()).orElse(null);
            return primitive != null && primitive.accessor() && primitive.synchronous()
                    && !expressions.suspends(expression);
        }
        return false;
    }

    /** Whether a statement takes no time: then nothing in it can suspend. */
    boolean isZeroDuration(StatementContext statement) {
        if (statement instanceof MASLParser.EmptyStmtContext) {
            return true;
        }
        if (statement instanceof MASLParser.ExpressionStmtContext expression) {
            return isZeroDuration(expression.expression()) && !queries.usesAbsentMember(expression)
                    && !queries.mayThrow(expression);
        }
        if (statement instanceof MASLParser.BlockStmtContext block) {
            for (StatementContext inner : block.block().statement()) {
                if (!isZeroDuration(inner)) {
                    return false;
                }
            }
            return true;
        }
        if (statement instanceof MASLParser.IfStmtContext ifStmt) {
            return !expressions.suspends(ifStmt.expression()) && isZeroDuration(ifStmt.thenStmt) && (ifStmt.elseStmt == null || isZeroDuration(ifStmt.elseStmt));
        }
        return false;
    }

    /** The initialisation or update part of a {@code for}: part of the loop, with no step boundary of its own. */
    void writeParts(List<ExpressionContext> parts) {
        for (ExpressionContext part : parts) {
            if (queries.usesAbsentMember(part)) {
                cases.comment("nothing for " + expressions.selfType().name() + ": its type lacks a member of "
                        + JavaText.snippet(part) + " (MASL 4)");
                continue;
            }
            writeGuarded(part, statementJava(part) + ";");
        }
    }
}
