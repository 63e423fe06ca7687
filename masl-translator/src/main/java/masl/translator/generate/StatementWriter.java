package masl.translator.generate;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.StringJoiner;
import masl.grammar.MASLParser.StatementContext;
import masl.grammar.MASLParser;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.Block;
import masl.translator.analysis.BlockMode;
import masl.translator.analysis.ESequence;
import masl.translator.analysis.EntryRef;
import masl.translator.analysis.Reaction;
import masl.translator.analysis.Sharing;
import masl.translator.analysis.Variable;
import masl.translator.parse.NumberLiterals;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * Translates a program's blocks and statements into the cases of one agent type's resumable state
 * machine, following masl-runtime/docs/generated-code-contract.md: every runtime call that may
 * suspend is a resumption point, each case is commented with its MASL line.
 */
final class StatementWriter {

    /** A loop being translated: where {@code exit} goes. */
    private record Loop(CaseWriter.Point exit) {
    }

    private final AnalyzedProgram program;
    private final StaticStructure structure;
    private final ExpressionWriter expressions;
    private final Unsupported unsupported;
    private final String file;
    private final CaseWriter cases = new CaseWriter();
    private final Map<MASLParser.EntryBlockContext, Block> blocksByTree = new IdentityHashMap<>();
    private final Map<Block, ESequence> sequenceStartingWith = new IdentityHashMap<>();
    private final Map<Block, CaseWriter.Point> tests = new IdentityHashMap<>();
    private final Map<Block, CaseWriter.Point> afters = new IdentityHashMap<>();
    private final Map<Block, CaseWriter.Point> firsts = new IdentityHashMap<>();
    /** How many entry tests were given a Java local of their own ({@code test$N}). */
    private int testsEvaluated;
    private final Map<Reaction, CaseWriter.Point> reactionPoints = new java.util.LinkedHashMap<>();
    private final Set<Block> keptOnReelect;
    private final LoopClassifier loops;
    private final InstructionWriter instructions;
    private Deque<Loop> loopStack = new ArrayDeque<>();
    private Block current;

    StatementWriter(AnalyzedProgram program, StaticStructure structure, ExpressionWriter expressions,
            Unsupported unsupported, String file, Set<Block> keptOnReelect) {
        this.program = program;
        this.structure = structure;
        this.expressions = expressions;
        this.unsupported = unsupported;
        this.file = file;
        this.keptOnReelect = keptOnReelect;
        this.loops = new LoopClassifier(program);
        this.instructions = new InstructionWriter(program, cases, expressions, file);
        if (program.root() != null) {
            index(program.root());
        }
    }

    private void index(Block block) {
        blocksByTree.put(block.tree(), block);
        for (ESequence sequence : block.sequences()) {
            sequenceStartingWith.put(sequence.blocks().get(0), sequence);
            sequence.blocks().forEach(this::index);
        }
    }

    /** The whole program of an agent: its arrival at {@code main}, then the end of its mission. */
    CaseWriter program() {
        Block root = program.root();
        if (root != null) {
            CaseWriter.Point end = cases.point();
            block(root, end);
            cases.place(end, file + ":" + root.tree().getStop().getLine() + ": after " + root.name());
            cases.suspending("ctx.endOfSequence(" + structure.topSequence(root) + ")", cases.point());
            cases.note(file + ":" + root.tree().getStop().getLine() + ": the end of the agent's program");
        } else {
            cases.place(cases.point(), file + ":1: a program without blocks only creates its agents");
        }
        cases.line("ctx.finish();");
        cases.endWithReturn();
        if (root != null) {
            reactions(root);
        }
        return cases;
    }

    /** Where the code of each reaction starts, for {@code reactionPc} (contract §7.3). */
    Map<Reaction, CaseWriter.Point> reactionPoints() {
        return reactionPoints;
    }

    // ------------------------------------------------------------------ reactions (§8)

    /** The reactions of {@code block} and of the blocks in it, each from its own case, after the body. */
    private void reactions(Block block) {
        for (Reaction reaction : block.reactions()) {
            reaction(reaction);
        }
        block.children().forEach(this::reactions);
    }

    /**
     * A reaction runs in one go: its instructions have no step boundary; it ends with its ending
     * statement or, at the end of its body, by leaving its block as {@code break} would.
     */
    private void reaction(Reaction reaction) {
        MASLParser.ReactionContext tree = reaction.tree();
        CaseWriter.Point start = cases.point();
        reactionPoints.put(reaction, start);
        cases.place(start, at(tree) + ": " + JavaText.header(tree));
        current = reaction.block();
        loopStack = new ArrayDeque<>();
        instructions.inReaction(true);
        statements(tree.statement());
        if (!cases.isTerminated()) {
            cases.note(file + ":" + tree.getStop().getLine() + ": the end of the reaction leaves " + current.name());
            endReaction();
            cases.line("ctx.breakOut(" + structure.block(current) + ");");
            cases.jump(afters.get(current));
        }
        instructions.inReaction(false);
        current = null;
    }

    /** In a reaction, before its ending: another reaction may follow, then this one does not decide. */
    private void endReaction() {
        if (instructions.isInReaction()) {
            cases.returnUnless("ctx.endReaction()");
        }
    }

    private String at(ParserRuleContext tree) {
        return file + ":" + tree.getStart().getLine();
    }

    private CaseWriter.Point test(Block block) {
        return tests.computeIfAbsent(block, b -> cases.point());
    }

    // ------------------------------------------------------------------ blocks (§6)

    private void sequence(ESequence sequence) {
        List<Block> blocks = sequence.blocks();
        CaseWriter.Point end = cases.point();
        for (int i = 0; i < blocks.size(); i++) {
            Block child = blocks.get(i);
            CaseWriter.Point next = i + 1 < blocks.size() ? test(blocks.get(i + 1)) : end;
            if (isOneInstruction(child)) {
                CaseWriter.Point childEnd = cases.point();
                block(child, childEnd);
                cases.place(childEnd, file + ":" + child.tree().getStop().getLine() + ": end of " + child.name()
                        + ", one instruction of " + current.name());
                cases.suspending("ctx.endOfChild(" + structure.block(child) + ")", cases.point());
            } else {
                block(child, next);
            }
        }
        Block last = blocks.get(blocks.size() - 1);
        StringJoiner names = new StringJoiner(", ", "{", "}");
        for (Block block : blocks) {
            names.add(block.name());
        }
        cases.place(end, file + ":" + last.tree().getStop().getLine() + ": end of the e-sequence " + names);
        cases.suspending("ctx.endOfSequence(" + structure.sequence(sequence) + ")", cases.point());
    }

    /** §6.4: an asynchronous or scalar child of a synchronous block is one instruction of it, also in an e-sequence. */
    private boolean isOneInstruction(Block child) {
        return current.mode() == BlockMode.SYNCHRONOUS && child.mode() != BlockMode.SYNCHRONOUS;
    }

    private void block(Block block, CaseWriter.Point after) {
        afters.put(block, after);
        MASLParser.EntryBlockContext tree = block.tree();
        String definition = structure.block(block);
        boolean keeps = keptOnReelect.contains(block) && hasLocals(block);
        cases.place(test(block), at(tree) + ": " + JavaText.header(tree));
        String test = expressions.condition(tree.test);
        instructions.awaitResults(tree.test);
        if (!test.equals("true") && !test.equals("false")) {
            // Evaluated before pc moves on to the body: an agent failing in the test is reported at the block.
            String value = "test$" + (++testsEvaluated);
            cases.line("boolean " + value + " = " + test + ";");
            test = value;
        }
        CaseWriter.Point body = cases.point();
        cases.setPc(body);
        cases.open("switch (ctx.enter(" + definition + ", " + test + ")) {");
        cases.jumpLine("case SKIPPED -> { " + (keeps ? expressions.keepFlag(block) + " = false; " : ""), after, " }");
        cases.returning("case WAITING -> { ", " }");
        cases.line("case ENTERED -> { }");
        cases.close("}");
        checkSize(tree.test);
        cases.place(body, null);

        Block outerBlock = current;
        Deque<Loop> outerLoops = loopStack;
        current = block;
        loopStack = new ArrayDeque<>();
        declarations(block, keeps);
        CaseWriter.Point first = cases.point();
        firsts.put(block, first);
        cases.place(first, null);
        for (MASLParser.BlockItemContext item : tree.blockItem()) {
            if (item.statement() != null) {
                statementInList(item.statement());
            }
        }
        current = outerBlock;
        loopStack = outerLoops;

        cases.place(cases.point(), file + ":" + tree.getStop().getLine() + ": end of " + block.name());
        cases.setPc(after);
        cases.returnUnless("ctx.leave(" + definition + ")");
    }

    private static boolean hasLocals(Block block) {
        return block.variables().stream().anyMatch(v -> v.sharing() == Sharing.LOCAL);
    }

    private void declarations(Block block, boolean keeps) {
        List<Variable> variables = block.variables();
        if (variables.isEmpty() && block.labels().isEmpty()) {
            return;
        }
        cases.note(at(!variables.isEmpty() && variables.get(0).initializer() != null ? variables.get(0).initializer()
                : block.tree()) + ": declarations of " + block.name());
        for (masl.translator.analysis.Label label : block.labels()) {
            // One label per member (LLabel) or per wave (SLabel, the first member of the wave makes it), MASL 10.
            cases.line(label.sharing() == Sharing.SHARED
                    ? "ctx.shared(" + structure.sharedLabel(label) + ").initialise(ctx::newLabel);"
                    : expressions.labels().localLabel(label) + " = ctx.newLabel();");
        }
        for (Variable variable : variables) {
            if (variable.sharing() == Sharing.SHARED && variable.initializer() != null) {
                cases.statementStart();
                String value = expressions.initializer(variable.type(), variable.initializer());
                boolean stepped = instructions.awaitResults(variable.initializer());
                cases.line("ctx.shared(" + structure.shared(variable) + ").initialise(() -> " + value + ");");
                stepAfterInitialiser(variable, stepped);
                checkSize(variable.initializer());
            }
        }
        CaseWriter.Point kept = cases.point();
        if (keeps) {
            // A step boundary cannot stand inside an if: a reelected member jumps over its locals instead.
            cases.open("if (" + expressions.keepFlag(block) + ") {");
            cases.comment("reelected: " + block.name() + "'s locals keep their values");
            cases.jump(kept);
            cases.close("}");
        }
        for (Variable variable : variables) {
            if (variable.sharing() == Sharing.LOCAL) {
                cases.statementStart();
                String value = localInitialValue(variable);
                boolean stepped = instructions.awaitResults(
                        variable.initializer() != null ? variable.initializer() : block.tree());
                cases.line(expressions.local(variable) + " = " + value + ";");
                stepAfterInitialiser(variable, stepped);
                checkSize(variable.initializer() != null ? variable.initializer() : block.tree());
            }
        }
        if (keeps) {
            cases.place(kept, null);
            cases.line(expressions.keepFlag(block) + " = false;");
        }
    }

    /**
     * An initialiser calling a primitive that is an instruction (contract §8.1) is followed by its
     * step boundary, as the same call in an assignment; unless waiting for its results took it already.
     */
    private void stepAfterInitialiser(Variable variable, boolean stepped) {
        if (!stepped && variable.initializer() != null
                && expressions.queries().callsInstruction(variable.initializer())) {
            instructions.stepAfter(variable.initializer());
        }
    }

    /** A local's initial value: its initialiser's, or the default value; a completed future for a future's holder. */
    private String localInitialValue(Variable variable) {
        if (expressions.holdsFuture(variable)) {
            if (variable.initializer() != null && variable.initializer().expression() != null) {
                return expressions.future(variable.type(), variable.initializer().expression());
            }
            return "CompletableFuture.completedFuture(" + JavaTypes.defaultValue(variable.type()) + ")";
        }
        return variable.initializer() == null ? JavaTypes.defaultValue(variable.type())
                : expressions.initializer(variable.type(), variable.initializer());
    }

    // ------------------------------------------------------------------ statements

    private void statements(List<StatementContext> statements) {
        for (StatementContext statement : statements) {
            statementInList(statement);
        }
    }

    /** A statement of a list: a block starting an e-sequence brings the whole e-sequence. */
    private void statementInList(StatementContext statement) {
        if (statement instanceof MASLParser.EntryStmtContext entry) {
            ESequence sequence = sequenceStartingWith.get(blocksByTree.get(entry.entryBlock()));
            if (sequence != null) {
                sequence(sequence);
            }
            return;
        }
        statement(statement);
    }

    private void statement(StatementContext statement) {
        cases.statementOwnCase();
        cases.statementStart();
        writeStatement(statement);
        checkSize(statement);
    }

    /** Reports a statement whose Java does not fit in a method, whatever the splitting. */
    private void checkSize(ParserRuleContext statement) {
        if (cases.tooLarge()) {
            unsupported.error(statement, "this statement is too large for Java, which holds at most 64 KB of bytecode"
                    + " in a method: split it into several statements");
        }
    }

    private void writeStatement(StatementContext statement) {
        if (statement instanceof MASLParser.EntryStmtContext) {
            statementInList(statement);
        } else if (statement instanceof MASLParser.BlockStmtContext block) {
            statements(block.block().statement());
        } else if (statement instanceof MASLParser.EmptyStmtContext) {
            return;
        } else if (statement instanceof MASLParser.ExpressionStmtContext expression) {
            instructions.write(expression);
        } else if (statement instanceof MASLParser.IfStmtContext ifStmt) {
            ifStatement(ifStmt);
        } else if (statement instanceof MASLParser.WhileStmtContext whileStmt) {
            whileStatement(whileStmt);
        } else if (statement instanceof MASLParser.ForStmtContext forStmt) {
            forStatement(forStmt);
        } else if (statement instanceof MASLParser.DoLoopStmtContext loop) {
            doLoop(loop);
        } else if (statement instanceof MASLParser.ExitStmtContext exit) {
            int levels = exit.levels == null ? 1 : NumberLiterals.count(exit.levels.getText());
            cases.note(at(exit) + ": " + JavaText.snippet(exit));
            cases.jump(loopStack.stream().skip(levels - 1).findFirst().orElseThrow().exit());
        } else if (statement instanceof MASLParser.BreakStmtContext breakStmt) {
            Block target = jumpTarget(breakStmt.jumpTarget());
            cases.note(at(breakStmt) + ": " + JavaText.snippet(breakStmt));
            endReaction();
            cases.line("ctx.breakOut(" + structure.block(target) + ");");
            cases.jump(afters.get(target));
        } else if (statement instanceof MASLParser.ReelectStmtContext reelect) {
            Block target = jumpTarget(reelect.jumpTarget());
            cases.note(at(reelect) + ": " + JavaText.snippet(reelect));
            endReaction();
            cases.line("ctx.reelect(" + structure.block(target) + ");");
            if (keptOnReelect.contains(target) && hasLocals(target)) {
                cases.line(expressions.keepFlag(target) + " = true;");
            }
            cases.jump(test(target));
        } else if (statement instanceof MASLParser.RestartStmtContext restart) {
            cases.note(at(restart) + ": restart;");
            endReaction();
            cases.line("ctx.restart(" + structure.block(current) + ");");
            cases.jump(firsts.get(current));
        } else if (statement instanceof MASLParser.ResumeStmtContext resume) {
            // Back to where the reactions interrupted the agent, completing the boundary it was at.
            cases.note(at(resume) + ": resume;");
            endReaction();
            cases.returnUnless("ctx.resumeInterrupted()");
            cases.end("continue;");
        } else if (statement instanceof MASLParser.ClearEventsStmtContext clear) {
            cases.note(at(clear) + ": " + JavaText.snippet(clear));
            cases.line("ctx.clearEvents();");
        } else if (statement instanceof MASLParser.EmitStmtContext emit) {
            instructions.emit(emit, emit.event, null);
        } else if (statement instanceof MASLParser.EmitWithMessageStmtContext emit) {
            instructions.emit(emit, emit.event, emit.message);
        } else if (statement instanceof MASLParser.SetAcceptStateStmtContext state) {
            instructions.setAcceptState(state);
        } else if (statement instanceof MASLParser.WaitStmtContext wait) {
            instructions.waitFor(wait);
        } else {
            unsupported.report(statement, "this statement");
        }
    }

    /** The block a {@code break}/{@code reelect} names: n-th outwards (1 = current), or by name. */
    private Block jumpTarget(MASLParser.JumpTargetContext target) {
        if (target != null && target.identifier() != null) {
            if (program.symbolOf(target.identifier()).orElse(null) instanceof EntryRef entry && entry.block() != null) {
                return entry.block();
            }
            String name = target.identifier().getText();
            for (Block block = current; block != null; block = block.parent()) {
                if (block.name().equals(name) || block.parent() == null && name.equals("main")) {
                    return block;
                }
            }
            throw new IllegalStateException("the analysis let through break or reelect to " + name);
        }
        int levels = target == null ? 1 : NumberLiterals.count(target.IntegerLiteral().getText());
        Block block = current;
        for (int i = 1; i < levels; i++) {
            block = block.parent();
        }
        return block;
    }

    // ------------------------------------------------------------------ control (MASL 12)

    private void ifStatement(MASLParser.IfStmtContext ifStmt) {
        cases.note(at(ifStmt) + ": " + JavaText.header(ifStmt));
        String condition = expressions.condition(ifStmt.expression());
        instructions.awaitResults(ifStmt.expression());
        if (instructions.isZeroDuration(ifStmt)) {
            // Nothing in it can suspend: a plain Java if.
            cases.open("if (" + condition + ") {");
            statement(ifStmt.thenStmt);
            if (ifStmt.elseStmt != null) {
                cases.reopen("} else {");
                statement(ifStmt.elseStmt);
            }
            cases.close("}");
            return;
        }
        CaseWriter.Point otherwise = cases.point();
        cases.jumpLine("if (!(" + condition + ")) { ", otherwise, " }");
        statement(ifStmt.thenStmt);
        if (ifStmt.elseStmt == null) {
            cases.place(otherwise, null);
            return;
        }
        CaseWriter.Point end = cases.point();
        cases.jump(end);
        cases.place(otherwise, at(ifStmt.elseStmt) + ": else");
        statement(ifStmt.elseStmt);
        cases.place(end, null);
    }

    private void whileStatement(MASLParser.WhileStmtContext loop) {
        CaseWriter.Point head = cases.point();
        CaseWriter.Point exit = cases.point();
        cases.place(head, at(loop) + ": " + JavaText.header(loop));
        String condition = expressions.condition(loop.expression());
        instructions.awaitResults(loop.expression());
        cases.jumpLine("if (!(" + condition + ")) { ", exit, " }");
        body(loop.statement(), exit);
        iteration(head, loops.isBusyWait(loop.expression(), loop.statement()));
        cases.place(exit, null);
    }

    private void forStatement(MASLParser.ForStmtContext loop) {
        cases.note(at(loop) + ": " + JavaText.header(loop));
        if (loop.init != null) {
            instructions.writeParts(loop.init.expression());
        }
        CaseWriter.Point head = cases.point();
        CaseWriter.Point exit = cases.point();
        cases.place(head, at(loop) + ": the test of " + JavaText.header(loop));
        if (loop.condition != null) {
            String condition = expressions.condition(loop.condition);
            instructions.awaitResults(loop.condition);
            cases.jumpLine("if (!(" + condition + ")) { ", exit, " }");
        }
        body(loop.statement(), exit);
        if (loop.update != null) {
            instructions.writeParts(loop.update.expression());
        }
        iteration(head, false);
        cases.place(exit, null);
    }

    private void doLoop(MASLParser.DoLoopStmtContext loop) {
        CaseWriter.Point head = cases.point();
        CaseWriter.Point exit = cases.point();
        cases.place(head, at(loop) + ": do { ... } loop");
        loopStack.push(new Loop(exit));
        statements(loop.block().statement());
        loopStack.pop();
        iteration(head, loops.isBusyWait(null, loop.block()));
        cases.place(exit, null);
    }

    private void body(StatementContext body, CaseWriter.Point exit) {
        loopStack.push(new Loop(exit));
        statement(body);
        loopStack.pop();
    }

    /** The end of an iteration (MASL 5): events and invocations, and parking if it is a busy-wait. */
    private void iteration(CaseWriter.Point head, boolean busyWait) {
        cases.setPc(head);
        cases.returnUnless("ctx." + (busyWait ? "busyWaitIteration" : "loopIteration") + "()");
        cases.end("continue;");
    }
}
