package masl.runtime;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Optional;
import java.util.Objects;
import masl.runtime.entry.Entry;

/**
 * The static description of an e-block (MASL §3, §6): its name, mode, parent block, the e-sequence
 * it belongs to, its shared variable and event declarations, its reactions and its children.
 * Generated programs hold one definition per block in {@code static final} fields, built in program
 * order before any mission runs; the per-mission state of the block is an {@link Entry}.
 */
public final class EntryDefinition {

    private final String name;
    private final Mode mode;
    private final EntryDefinition parent;
    private final ESequence sequence;
    private final List<EntryDefinition> children = new ArrayList<>();
    private final List<SharedDeclaration<?>> sharedDeclarations = new ArrayList<>();
    private final List<Event> events = new ArrayList<>();
    /** In the order written: their priority (§8). Copied on write: read at every event processing. */
    private volatile List<Reaction> reactions = List.of();

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
        return declareShared(variableName, initialValue, null);
    }

    /**
     * Declares a shared variable that holds an array of type {@code type} (MASL §7), null until its
     * initialiser runs; the type is what a deployed agent's copy of the array is made of.
     */
    public <T> SharedDeclaration<T> declareSharedArray(String variableName, Class<T> type) {
        return declareShared(variableName, null, type);
    }

    private <T> SharedDeclaration<T> declareShared(String variableName, T initialValue, Class<T> type) {
        synchronized (sharedDeclarations) {
            SharedDeclaration<T> declaration =
                    new SharedDeclaration<>(this, variableName, sharedDeclarations.size(), initialValue, type);
            sharedDeclarations.add(declaration);
            return declaration;
        }
    }

    /** Declares {@code local event name;} (MASL §8): perceived only by the agent that emits it. */
    public Event declareLocalEvent(String name) {
        return declareEvent(name, false);
    }

    /** Declares {@code shared event name;} (MASL §8): perceived by every member of this block at emission. */
    public Event declareSharedEvent(String name) {
        return declareEvent(name, true);
    }

    /** The shared event {@code eventName} this block declares, if it does. */
    Optional<Event> sharedEvent(String eventName) {
        synchronized (events) {
            return events.stream().filter(event -> event.isShared() && event.name().equals(eventName)).findFirst();
        }
    }

    /** The event {@code eventName} this block declares, shared or local, if it does. */
    Optional<Event> event(String eventName) {
        synchronized (events) {
            return events.stream().filter(event -> event.name().equals(eventName)).findFirst();
        }
    }

    private Event declareEvent(String eventName, boolean shared) {
        synchronized (events) {
            if (events.stream().anyMatch(event -> event.name().equals(eventName))) {
                throw new IllegalArgumentException("block " + name + " already declares event " + eventName);
            }
            Event event = new Event(eventName, shared, this);
            events.add(event);
            return event;
        }
    }

    /**
     * Declares this block's next reaction, {@code react (event) { … }}; declare a block's reactions
     * in the order they are written.
     *
     * @throws IllegalArgumentException if {@code event} is neither a system event nor declared by
     *     this block or an enclosing one, or if this block already reacts to it
     */
    public Reaction react(Event event) {
        if (!event.isSystemEvent() && !isWithin(event.block())) {
            throw new IllegalArgumentException(event + " is not visible in block " + name);
        }
        return addReaction(event);
    }

    /** Declares this block's next reaction, {@code react (default) { … }}. */
    public Reaction reactToDefault() {
        return addReaction(null);
    }

    private synchronized Reaction addReaction(Event event) {
        if (reactions.stream().anyMatch(reaction -> reaction.event() == event)) {
            throw new IllegalArgumentException("block " + name + " already reacts to "
                    + (event == null ? "default" : event.name()));
        }
        Reaction reaction = new Reaction(this, event, reactions.size());
        List<Reaction> more = new ArrayList<>(reactions);
        more.add(reaction);
        reactions = List.copyOf(more);
        return reaction;
    }

    /** This block's reactions in the order written. */
    public List<Reaction> reactions() {
        return reactions;
    }

    /**
     * The reaction of this block to an occurrence of {@code event} (§8): its {@code react(event)},
     * else its {@code react(default)}, else {@code null} (look in the parent).
     */
    public Reaction reactionTo(Event event) {
        Reaction fallback = null;
        for (Reaction reaction : reactions) {
            if (reaction.event() == event) {
                return reaction;
            }
            if (reaction.isDefault()) {
                fallback = reaction;
            }
        }
        return fallback;
    }

    /** Whether this block is {@code block} or nested in it. */
    boolean isWithin(EntryDefinition block) {
        for (EntryDefinition b = this; b != null; b = b.parent) {
            if (b == block) {
                return true;
            }
        }
        return false;
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

    /** <b>Internal:</b> not part of the API. */
    public List<SharedDeclaration<?>> sharedDeclarations() {
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
