package masl.translator.analysis;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import masl.grammar.MASLParser;

/**
 * An entry block (MASL §6) with what it declares. The top-level block is the root ({@link #parent()}
 * null); {@code main} names it whatever its own name. Filled in by the analysis, read-only afterwards.
 */
public final class Block {

    private final String name;
    private final BlockMode mode;
    private final Block parent;
    private final MASLParser.EntryBlockContext tree;
    private final List<ESequence> sequences = new ArrayList<>();
    private final List<Variable> variables = new ArrayList<>();
    private final List<EventDecl> events = new ArrayList<>();
    private final List<Label> labels = new ArrayList<>();
    private final List<Reaction> reactions = new ArrayList<>();

    Block(String name, BlockMode mode, Block parent, MASLParser.EntryBlockContext tree) {
        this.name = name;
        this.mode = mode;
        this.parent = parent;
        this.tree = tree;
    }

    public String name() {
        return name;
    }

    public BlockMode mode() {
        return mode;
    }

    /** The enclosing block, null for the top-level one. */
    public Block parent() {
        return parent;
    }

    /** 1 for the top-level block, 2 for its children, … */
    public int depth() {
        return parent == null ? 1 : parent.depth() + 1;
    }

    public MASLParser.EntryBlockContext tree() {
        return tree;
    }

    /** The child blocks, grouped in e-sequences, in source order. */
    public List<ESequence> sequences() {
        return Collections.unmodifiableList(sequences);
    }

    /** The child blocks in source order. */
    public List<Block> children() {
        List<Block> children = new ArrayList<>();
        for (ESequence sequence : sequences) {
            children.addAll(sequence.blocks());
        }
        return Collections.unmodifiableList(children);
    }

    public List<Variable> variables() {
        return Collections.unmodifiableList(variables);
    }

    public List<EventDecl> events() {
        return Collections.unmodifiableList(events);
    }

    public List<Label> labels() {
        return Collections.unmodifiableList(labels);
    }

    /** In source order, which is their priority (§8). */
    public List<Reaction> reactions() {
        return Collections.unmodifiableList(reactions);
    }

    void addSequence(ESequence sequence) {
        sequences.add(sequence);
    }

    void addVariable(Variable variable) {
        variables.add(variable);
    }

    void addEvent(EventDecl event) {
        events.add(event);
    }

    void addLabel(Label label) {
        labels.add(label);
    }

    void addReaction(Reaction reaction) {
        reactions.add(reaction);
    }

    @Override
    public String toString() {
        return mode.keyword() + " entry " + name;
    }
}
