package masl.runtime;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;

/**
 * The static description of an e-block (MASL §3, §6): its name, mode, parent block, the e-sequence
 * it belongs to, its shared variable declarations and its children. Generated programs hold one
 * definition per block in {@code static final} fields, built in program order before any mission
 * runs; the per-mission state of the block is an {@link Entry}.
 */
public final class EntryDefinition {

    private final String name;
    private final Mode mode;
    private final EntryDefinition parent;
    private final ESequence sequence;
    private final List<EntryDefinition> children = new ArrayList<>();
    private final List<SharedDeclaration<?>> sharedDeclarations = new ArrayList<>();

    EntryDefinition(String name, Mode mode, EntryDefinition parent, ESequence sequence) {
        if (Objects.requireNonNull(name, "name").isEmpty()) {
            throw new IllegalArgumentException("an e-block needs a name");
        }
        this.name = name;
        this.mode = Objects.requireNonNull(mode, "mode");
        this.parent = parent;
        this.sequence = sequence;
    }

    /** Defines the top-level block of a program ({@code main}, whatever its name in the source). */
    public static EntryDefinition main(String name, Mode mode) {
        ESequence top = new ESequence(null);
        EntryDefinition main = new EntryDefinition(name, mode, null, top);
        top.addMain(main);
        return main;
    }

    /** Starts a new e-sequence in this block's body; add its blocks with {@link ESequence#block}. */
    public ESequence newSequence() {
        return new ESequence(this);
    }

    /** Defines a child block that stands alone: an e-sequence of one block. */
    public EntryDefinition child(String name, Mode mode) {
        return newSequence().block(name, mode);
    }

    /**
     * Declares a shared variable of this block (MASL §7): one copy per wave, holding
     * {@code initialValue} (the type's default value) until its initialiser runs.
     */
    public <T> SharedDeclaration<T> declareShared(String variableName, T initialValue) {
        synchronized (sharedDeclarations) {
            SharedDeclaration<T> declaration =
                    new SharedDeclaration<>(this, variableName, sharedDeclarations.size(), initialValue);
            sharedDeclarations.add(declaration);
            return declaration;
        }
    }

    public String name() {
        return name;
    }

    public Mode mode() {
        return mode;
    }

    /** The enclosing block, or {@code null} for {@code main}. */
    public EntryDefinition parent() {
        return parent;
    }

    public ESequence sequence() {
        return sequence;
    }

    /** The blocks directly nested in this one, in program order. */
    public List<EntryDefinition> children() {
        synchronized (children) {
            return Collections.unmodifiableList(new ArrayList<>(children));
        }
    }

    List<SharedDeclaration<?>> sharedDeclarations() {
        synchronized (sharedDeclarations) {
            return new ArrayList<>(sharedDeclarations);
        }
    }

    void adopt(EntryDefinition child) {
        synchronized (children) {
            children.add(child);
        }
    }

    @Override
    public String toString() {
        return mode.name().toLowerCase() + " entry " + name;
    }
}
