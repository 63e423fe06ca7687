package masl.runtime;

import java.util.Objects;

/**
 * A declared event (MASL §8): its name, whether it is {@code local} (perceived by the emitting agent
 * only) or {@code shared} (perceived by every member of the declaring block at emission, emitter
 * included), and the declaring block. Generated programs hold one instance per declaration in a
 * {@code static final} field, made by {@link EntryDefinition#declareLocalEvent} or
 * {@link EntryDefinition#declareSharedEvent}; events are compared by identity.
 *
 * <p>The three system events are local, declared by no block, and usable in every block.
 */
public final class Event {

    /** An invocation made by this agent was ignored by permeability, or timed out (§8, §11). */
    public static final Event TIMEOUT = new Event("timeout", false, null);
    /** A primitive or a Java call threw; the message is the exception's class name (§8, §9). */
    public static final Event UNCAUGHT_EXCEPTION = new Event("uncaught_exception", false, null);
    /** A denied attribute access or {@code limited} write (§7, §11). */
    public static final Event FORBIDDEN_ACCESS = new Event("forbidden_access", false, null);

    private final String name;
    private final boolean shared;
    private final EntryDefinition block;

    Event(String name, boolean shared, EntryDefinition block) {
        if (Objects.requireNonNull(name, "name").isEmpty()) {
            throw new IllegalArgumentException("an event needs a name");
        }
        this.name = name;
        this.shared = shared;
        this.block = block;
    }

    public String name() {
        return name;
    }

    /** {@code shared event}: perceived by every member of the declaring block. */
    public boolean isShared() {
        return shared;
    }

    /** The declaring block, or {@code null} for a system event. */
    public EntryDefinition block() {
        return block;
    }

    public boolean isSystemEvent() {
        return block == null;
    }

    @Override
    public String toString() {
        if (block == null) {
            return "system event " + name;
        }
        return (shared ? "shared" : "local") + " event " + name + " of " + block.name();
    }
}
