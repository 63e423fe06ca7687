package masl.translator.analysis;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import masl.grammar.MASLParser.StatementContext;
import masl.grammar.MASLParser;
import masl.translator.diagnostics.Suggestions;
import masl.translator.parse.NumberLiterals;
import masl.translator.parse.ProgramParser;

/**
 * Walks the blocks with their scopes: declares what each block declares (MASL §3, §7, §8, §10), checks
 * the statements that depend on where they stand (jumps §6.5/§6.6, {@code exit} §12, {@code resume} and
 * {@code clearEvents} §8) and has every expression typed.
 */
final class BlockChecker {

    /** The statements that are one word, for a lone word standing as a statement. */
    private static final List<String> STATEMENT_WORDS = List.of("break", "exit", "reelect", "restart", "resume",
            "clearEvents");

    private final Errors errors;
    private final Map<MASLParser.EntryBlockContext, Block> blocks;
    private final TypeNames typeNames;
    private final EntryNames entryNames;
    private final ExpressionTyper typer;
    private final Bindings bindings;

    /** Where the walk stands: the innermost block, its scope, the loops around since it, and whether in a reaction. */
    private Block current;
    private Scope scope;
    private int loopDepth;
    private boolean inReaction;

    BlockChecker(Errors errors, Map<MASLParser.EntryBlockContext, Block> blocks, TypeNames typeNames,
            EntryNames entryNames, ExpressionTyper typer, Bindings bindings) {
        this.errors = errors;
        this.blocks = blocks;
        this.typeNames = typeNames;
        this.entryNames = entryNames;
        this.typer = typer;
        this.bindings = bindings;
    }

    void check(MASLParser.EntryBlockContext tree, Scope enclosing) {
        Block savedBlock = current;
        Scope savedScope = scope;
        int savedLoops = loopDepth;
        boolean savedInReaction = inReaction;

        Block block = blocks.get(tree);
        // The test is evaluated before the agent enters: the block's own names are not visible in it.
        typer.useScope(enclosing);
        typer.checkCondition(tree.test, "the test of entry " + block.name());
        current = block;
        scope = new Scope(enclosing);
        typer.useScope(scope);
        loopDepth = 0;
        inReaction = false;
        boolean instructionSeen = false;
        for (MASLParser.BlockItemContext item : tree.blockItem()) {
            if (item.declaration() != null) {
                // A declaration whose `local` the user left out was told to go at the head of its block.
                if (instructionSeen && !ProgramParser.wasLeftOut(item.declaration().getStart())) {
                    errors.at(item.declaration(),
                            "declarations must come before the instructions and reactions of block " + block.name());
                }
                declare(item.declaration());
            } else if (item.reaction() != null) {
                instructionSeen = true;
                checkReaction(item.reaction());
            } else {
                instructionSeen = true;
                statement(item.statement());
            }
        }

        current = savedBlock;
        scope = savedScope;
        loopDepth = savedLoops;
        inReaction = savedInReaction;
        typer.useScope(savedScope);
    }

    // ------------------------------------------------------------------ declarations

    private void declare(MASLParser.DeclarationContext declaration) {
        if (declaration instanceof MASLParser.VariableDeclContext variables) {
            declareVariables(variables);
        } else if (declaration instanceof MASLParser.EventDeclContext events) {
            Sharing sharing = events.scope.getType() == MASLParser.SHARED ? Sharing.SHARED : Sharing.LOCAL;
            for (MASLParser.IdentifierContext name : events.identifierList().identifier()) {
                EventDecl event = new EventDecl(name.getText(), sharing, current);
                if (declareName(name, event)) {
                    current.addEvent(event);
                }
            }
        } else {
            MASLParser.LabelDeclContext labels = (MASLParser.LabelDeclContext) declaration;
            Sharing sharing = labels.kind.getType() == MASLParser.SLABEL ? Sharing.SHARED : Sharing.LOCAL;
            for (MASLParser.IdentifierContext name : labels.identifierList().identifier()) {
                Label label = new Label(name.getText(), sharing, current);
                if (declareName(name, label)) {
                    current.addLabel(label);
                }
            }
        }
    }

    /** {@code local int a, b = 0;}: the one initialiser initialises every name (the grammar's reading of §3). */
    private void declareVariables(MASLParser.VariableDeclContext declaration) {
        MaslType type = typeNames.resolve(declaration.javaType(), errors);
        ImportedType limitedTo = null;
        if (declaration.limitedTo() != null) {
            MASLParser.IdentifierContext typeName = declaration.limitedTo().typeName;
            limitedTo = typeNames.agentType(typeName.getText()).orElse(null);
            if (limitedTo == null) {
                errors.at(typeName, "cannot find agent type " + typeName.getText() + " in limited(" + typeName.getText()
                        + ")");
            }
        }
        MASLParser.VariableInitializerContext initializer = declaration.variableInitializer();
        if (initializer != null) {
            // Checked before the names exist: `local int x = x;` reads no x.
            typer.checkInitializer(type, initializer);
        }
        Sharing sharing = declaration.scope.getType() == MASLParser.SHARED ? Sharing.SHARED : Sharing.LOCAL;
        for (MASLParser.IdentifierContext name : declaration.identifierList().identifier()) {
            Variable variable = new Variable(name.getText(), type, sharing, declaration.FINAL() != null, limitedTo,
                    initializer, current);
            if (declareName(name, variable)) {
                current.addVariable(variable);
            }
        }
    }

    /** §3: a name may not be declared twice in a block nor hide one visible from an enclosing block. */
    private boolean declareName(MASLParser.IdentifierContext name, Symbol symbol) {
        Optional<Symbol> visible = scope.resolve(name.getText());
        if (visible.isPresent()) {
            errors.at(name, name.getText() + " is already declared " + whereDeclared(visible.get()));
            return false;
        }
        scope.declare(name.getText(), symbol);
        bindings.bind(name, symbol);
        return true;
    }

    private String whereDeclared(Symbol symbol) {
        Block owner = null;
        if (symbol instanceof Variable variable) {
            owner = variable.block();
        } else if (symbol instanceof EventDecl event) {
            if (event.isSystemEvent()) {
                return "as a system event";
            }
            owner = event.block();
        } else if (symbol instanceof Label label) {
            owner = label.block();
        } else if (symbol instanceof AgentDecl) {
            return "as an agent";
        }
        if (owner == current) {
            return "in block " + current.name();
        }
        return owner == null ? "" : "in enclosing block " + owner.name();
    }

    // ------------------------------------------------------------------ reactions and statements

    private void checkReaction(MASLParser.ReactionContext reaction) {
        EventDecl event = null;
        if (reaction.event != null) {
            event = typer.event(reaction.event).orElse(null);
            if (event == null) {
                statements(reaction);
                return;
            }
        }
        EventDecl reactedTo = event;
        if (current.reactions().stream().anyMatch(existing -> existing.event() == reactedTo)) {
            errors.at(reaction, "block " + current.name() + " already reacts to "
                    + (reactedTo == null ? "default" : reactedTo.name()));
        } else {
            current.addReaction(new Reaction(event, current, reaction));
        }
        statements(reaction);
    }

    /** A reaction's statements: no loop around them, and {@code resume}/{@code clearEvents} allowed. */
    private void statements(MASLParser.ReactionContext reaction) {
        boolean savedInReaction = inReaction;
        int savedLoops = loopDepth;
        inReaction = true;
        loopDepth = 0;
        for (StatementContext statement : reaction.statement()) {
            statement(statement);
        }
        inReaction = savedInReaction;
        loopDepth = savedLoops;
    }

    private void statement(StatementContext statement) {
        if (statement instanceof MASLParser.EntryStmtContext entry) {
            check(entry.entryBlock(), scope);
        } else if (statement instanceof MASLParser.BlockStmtContext block) {
            block.block().statement().forEach(this::statement);
        } else if (statement instanceof MASLParser.ExpressionStmtContext expression) {
            expressionStatement(expression.expression());
        } else if (statement instanceof MASLParser.IfStmtContext ifStmt) {
            typer.checkCondition(ifStmt.expression(), "the condition of if");
            statement(ifStmt.thenStmt);
            if (ifStmt.elseStmt != null) {
                statement(ifStmt.elseStmt);
            }
        } else if (statement instanceof MASLParser.WhileStmtContext whileStmt) {
            typer.checkCondition(whileStmt.expression(), "the condition of while");
            loopBody(() -> statement(whileStmt.statement()));
        } else if (statement instanceof MASLParser.ForStmtContext forStmt) {
            forStatement(forStmt);
        } else if (statement instanceof MASLParser.DoLoopStmtContext loop) {
            loopBody(() -> loop.block().statement().forEach(this::statement));
        } else {
            jumpOrEventStatement(statement);
        }
    }

    private void forStatement(MASLParser.ForStmtContext forStmt) {
        if (forStmt.init != null) {
            forStmt.init.expression().forEach(this::expressionStatement);
        }
        if (forStmt.condition != null) {
            typer.checkCondition(forStmt.condition, "the condition of for");
        }
        if (forStmt.update != null) {
            forStmt.update.expression().forEach(this::expressionStatement);
        }
        loopBody(() -> statement(forStmt.statement()));
    }

    private void loopBody(Runnable body) {
        loopDepth++;
        body.run();
        loopDepth--;
    }

    private void jumpOrEventStatement(StatementContext statement) {
        if (statement instanceof MASLParser.ExitStmtContext exit) {
            checkExit(exit);
        } else if (statement instanceof MASLParser.BreakStmtContext jump) {
            checkJump("break", jump.jumpTarget());
        } else if (statement instanceof MASLParser.ReelectStmtContext jump) {
            checkJump("reelect", jump.jumpTarget());
        } else if (statement instanceof MASLParser.ResumeStmtContext
                || statement instanceof MASLParser.ClearEventsStmtContext) {
            if (!inReaction) {
                errors.at(statement, statement.getStart().getText() + " can only be used in a reaction");
            }
        } else if (statement instanceof MASLParser.EmitStmtContext emit) {
            typer.event(emit.event);
        } else if (statement instanceof MASLParser.EmitWithMessageStmtContext emit) {
            typer.event(emit.event);
            typer.type(emit.message);
        } else if (statement instanceof MASLParser.SetAcceptStateStmtContext setState) {
            typer.type(setState.expression());
        } else if (statement instanceof MASLParser.WaitStmtContext waitStmt) {
            typer.type(waitStmt.state);
            if (waitStmt.timeout != null) {
                MaslType timeout = typer.type(waitStmt.timeout);
                if (!TypeRules.isOpen(timeout) && !TypeRules.isNumeric(timeout)) {
                    errors.at(waitStmt.timeout, "the timeout of wait must be a number of milliseconds, found "
                            + timeout.describe());
                }
            }
        }
    }

    /**
     * Java's rule: only assignments, increments, calls and object creations may stand as statements.
     * A lone word ({@code return;}, {@code brek;}) is one mistake, reported once with the statement meant.
     */
    private void expressionStatement(MASLParser.ExpressionContext expression) {
        if (expression instanceof MASLParser.PrimaryExprContext primary
                && primary.primary() instanceof MASLParser.NameExprContext name) {
            String word = name.getText();
            errors.at(expression, word.equals("return")
                    ? "MASL has no return: `break;` leaves the block, `exit;` the loop"
                    : "not a statement: " + word + Suggestions.closest(word, STATEMENT_WORDS)
                            .map(keyword -> "; did you mean `" + keyword + ";`?").orElse(""));
            return;
        }
        typer.type(expression);
        boolean isStatement = expression instanceof MASLParser.AssignExprContext
                || expression instanceof MASLParser.PostfixExprContext
                || expression instanceof MASLParser.PrefixExprContext prefix
                        && (prefix.op.getType() == MASLParser.INC || prefix.op.getType() == MASLParser.DEC)
                || expression instanceof MASLParser.MethodCallContext
                || expression instanceof MASLParser.PrimaryExprContext primary
                        && (primary.primary() instanceof MASLParser.SelfInvocationContext
                                || primary.primary() instanceof MASLParser.PlainCallContext
                                || primary.primary() instanceof MASLParser.NewExprContext);
        if (!isStatement) {
            errors.at(expression, "not a statement: " + expression.getText());
        }
    }

    private void checkExit(MASLParser.ExitStmtContext exit) {
        int levels = exit.levels == null ? 1 : NumberLiterals.count(exit.levels.getText());
        if (loopDepth == 0) {
            errors.at(exit, "exit outside a loop");
        } else if (levels < 1) {
            errors.at(exit.levels, "exit needs a positive number of loops");
        } else if (levels > loopDepth) {
            errors.at(exit.levels, "exit(" + exit.levels.getText() + ") leaves " + exit.levels.getText()
                    + " loops but only " + loopDepth + (loopDepth == 1 ? " encloses" : " enclose") + " it");
        }
    }

    /** {@code break}/{@code reelect}: a count of blocks, from the current one (§8: a reaction's block), or a name. */
    private void checkJump(String keyword, MASLParser.JumpTargetContext target) {
        if (target == null) {
            return;
        }
        if (target.identifier() != null) {
            String name = target.identifier().getText();
            Optional<Block> block = entryNames.enclosing(name, current);
            if (block.isPresent()) {
                bindings.bind(target.identifier(), new EntryRef(name, block.get()));
            } else {
                errors.at(target.identifier(), keyword + "(" + name + "): " + name + " is not an enclosing block");
            }
            return;
        }
        int levels = NumberLiterals.count(target.IntegerLiteral().getText());
        int depth = current.depth();
        if (levels < 1) {
            errors.at(target, keyword + " needs a positive number of blocks");
        } else if (levels > depth) {
            errors.at(target, keyword + "(" + target.getText() + ") leaves " + target.getText() + " blocks but only "
                    + depth + (depth == 1 ? " encloses" : " enclose") + " it");
        }
    }
}
