package masl.translator.analysis;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.StatementContext;

/**
 * Builds the tree of entry blocks and their e-sequences before names are resolved, since an entry's
 * members may be used before its block ({@code turn.lock()} in E6). Checks what the tree alone decides:
 * unique entry names (MASL §3), the nesting matrix of §6.4, and that no block stands in a reaction.
 * A block nested in an {@code if}, a loop or a {@code { }} is a child of the enclosing entry block.
 */
final class BlockTreeBuilder {

    private final Errors errors;
    private final Map<MASLParser.EntryBlockContext, Block> blocks = new IdentityHashMap<>();
    private final Map<String, Block> blocksByName = new LinkedHashMap<>();

    BlockTreeBuilder(Errors errors) {
        this.errors = errors;
    }

    Block build(MASLParser.EntryBlockContext root) {
        return block(root, null, false);
    }

    Map<MASLParser.EntryBlockContext, Block> blocks() {
        return blocks;
    }

    Map<String, Block> blocksByName() {
        return blocksByName;
    }

    private Block block(MASLParser.EntryBlockContext tree, Block parent, boolean inReaction) {
        BlockMode mode = BlockMode.valueOf(tree.blockMode().getText().toUpperCase(Locale.ROOT));
        String name = tree.name.getText();
        if (parent != null && parent.mode() == BlockMode.SCALAR && mode != BlockMode.SCALAR) {
            errors.at(tree.blockMode(), "a " + mode.keyword() + " block cannot be nested in scalar block "
                    + parent.name() + ": only scalar blocks may be");
        }
        if (inReaction) {
            errors.at(tree, "entry block " + name + " cannot stand in a reaction");
        }
        Block block = new Block(name, mode, parent, tree);
        blocks.put(tree, block);
        // `main` always denotes the top-level block (§3), so no other block may take that name.
        if (blocksByName.containsKey(name) || name.equals(EntryNames.MAIN) && parent != null) {
            errors.at(tree.name, "entry name " + name + " is already used by another block");
        } else {
            blocksByName.put(name, block);
        }
        SequenceCollector sequences = new SequenceCollector(block, inReaction);
        for (MASLParser.BlockItemContext item : tree.blockItem()) {
            if (item.reaction() != null) {
                scanReaction(item.reaction(), block);
            } else if (item.statement() instanceof MASLParser.EntryStmtContext entry) {
                sequences.add(entry.entryBlock());
            } else {
                sequences.end();
                if (item.statement() != null) {
                    scan(item.statement(), block, inReaction);
                }
            }
        }
        sequences.end();
        return block;
    }

    private void scanReaction(MASLParser.ReactionContext reaction, Block owner) {
        scanAll(reaction.statement(), owner, true);
    }

    private void scanAll(List<StatementContext> statements, Block owner, boolean inReaction) {
        SequenceCollector sequences = new SequenceCollector(owner, inReaction);
        for (StatementContext statement : statements) {
            if (statement instanceof MASLParser.EntryStmtContext entry) {
                sequences.add(entry.entryBlock());
            } else {
                sequences.end();
                scan(statement, owner, inReaction);
            }
        }
        sequences.end();
    }

    /** Finds the blocks nested in a statement that is not itself an entry block. */
    private void scan(StatementContext statement, Block owner, boolean inReaction) {
        if (statement instanceof MASLParser.BlockStmtContext block) {
            scanAll(block.block().statement(), owner, inReaction);
        } else if (statement instanceof MASLParser.IfStmtContext ifStmt) {
            scanAll(List.of(ifStmt.thenStmt), owner, inReaction);
            if (ifStmt.elseStmt != null) {
                scanAll(List.of(ifStmt.elseStmt), owner, inReaction);
            }
        } else if (statement instanceof MASLParser.WhileStmtContext whileStmt) {
            scanAll(List.of(whileStmt.statement()), owner, inReaction);
        } else if (statement instanceof MASLParser.ForStmtContext forStmt) {
            scanAll(List.of(forStmt.statement()), owner, inReaction);
        } else if (statement instanceof MASLParser.DoLoopStmtContext loop) {
            scanAll(loop.block().statement(), owner, inReaction);
        }
    }

    /** Gathers consecutive entry blocks of one statement list into an e-sequence of their parent. */
    private final class SequenceCollector {
        private final Block parent;
        private final boolean inReaction;
        private final List<MASLParser.EntryBlockContext> pending = new ArrayList<>();

        SequenceCollector(Block parent, boolean inReaction) {
            this.parent = parent;
            this.inReaction = inReaction;
        }

        void add(MASLParser.EntryBlockContext tree) {
            pending.add(tree);
        }

        void end() {
            if (pending.isEmpty()) {
                return;
            }
            List<Block> sequence = new ArrayList<>();
            for (MASLParser.EntryBlockContext tree : pending) {
                sequence.add(block(tree, parent, inReaction));
            }
            parent.addSequence(new ESequence(sequence));
            pending.clear();
        }
    }
}
