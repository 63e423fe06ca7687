package masl.runtime;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * An e-sequence (MASL §6.1): e-blocks of one parent that follow each other with no other
 * instruction between them. A block standing alone is an e-sequence of one block. The end of an
 * e-sequence is where an active member of a synchronous parent that did not run a synchronous
 * block of it reaches the parent's barrier (§6.4); see {@link AgentContext#endOfSequence}.
 *
 * <p>Built once, by the generated program's static initialisers, before any mission runs.
 */
public final class ESequence {

    private final EntryDefinition parent;
    private final List<EntryDefinition> blocks = new ArrayList<>();

    ESequence(EntryDefinition parent) {
        this.parent = parent;
    }

    /** The block whose body holds this e-sequence, or {@code null} for the e-sequence of {@code main}. */
    public EntryDefinition parent() {
        return parent;
    }

    /** The blocks of this e-sequence in program order. */
    public List<EntryDefinition> blocks() {
        synchronized (blocks) {
            return Collections.unmodifiableList(new ArrayList<>(blocks));
        }
    }

    /**
     * Appends a block to this e-sequence.
     *
     * @throws IllegalArgumentException if this e-sequence is the top level one (it holds {@code main}
     *     only), the name is empty, or a non-scalar block would be nested in a scalar one (§6.6)
     */
    public EntryDefinition block(String name, Mode mode) {
        if (parent == null) {
            throw new IllegalArgumentException("the top-level e-sequence holds main only");
        }
        if (parent.mode() == Mode.SCALAR && mode != Mode.SCALAR) {
            throw new IllegalArgumentException("a " + mode + " block cannot be nested in scalar block " + parent.name());
        }
        EntryDefinition block = new EntryDefinition(name, mode, parent, this);
        synchronized (blocks) {
            blocks.add(block);
        }
        parent.adopt(block);
        return block;
    }

    /**
     * Whether {@code block} is the last block of this e-sequence, after which it ends.
     * <b>Internal:</b> not part of the API.
     */
    public boolean endsWith(EntryDefinition block) {
        synchronized (blocks) {
            return blocks.get(blocks.size() - 1) == block;
        }
    }

    void addMain(EntryDefinition main) {
        synchronized (blocks) {
            blocks.add(main);
        }
    }

    @Override
    public String toString() {
        return "e-sequence" + blocks();
    }
}
