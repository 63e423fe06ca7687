package masl.runtime;

/**
 * A {@code react (e) { … }} or {@code react (default) { … }} of a block (MASL §8). A block's
 * reactions are declared in the order they are written, which is their priority: an occurrence
 * whose reaction comes first in the block is reacted to first. Made by {@link EntryDefinition#react}
 * and {@link EntryDefinition#reactToDefault}; the program says where each reaction's code starts
 * with {@link AgentProgram#reactionPc}.
 */
public final class Reaction {

    private final EntryDefinition block;
    private final Event event;
    private final int priority;

    Reaction(EntryDefinition block, Event event, int priority) {
        this.block = block;
        this.event = event;
        this.priority = priority;
    }

    /** The block whose body holds the reaction: its {@code break}, {@code restart}, … count from there. */
    public EntryDefinition block() {
        return block;
    }

    /** The event reacted to, or {@code null} for {@code react(default)}. */
    public Event event() {
        return event;
    }

    public boolean isDefault() {
        return event == null;
    }

    /** 0 for the block's first reaction, 1 for the next one written, … */
    public int priority() {
        return priority;
    }

    @Override
    public String toString() {
        return "react(" + (event == null ? "default" : event.name()) + ") of " + block.name();
    }
}
