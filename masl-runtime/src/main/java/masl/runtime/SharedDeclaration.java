package masl.runtime;

/**
 * The declaration of a shared variable ({@code shared T x = e;}, MASL §7) of one block; the
 * variable itself exists once per wave of that block and is reached through
 * {@link AgentContext#shared(SharedDeclaration)}.
 *
 * @param <T> the variable's (boxed) Java type
 */
public final class SharedDeclaration<T> {

    private final EntryDefinition block;
    private final String name;
    private final int index;
    private final T initialValue;

    SharedDeclaration(EntryDefinition block, String name, int index, T initialValue) {
        this.block = block;
        this.name = name;
        this.index = index;
        this.initialValue = initialValue;
    }

    public EntryDefinition block() {
        return block;
    }

    public String name() {
        return name;
    }

    /** The value before the initialiser ran: the default value of the type. */
    public T initialValue() {
        return initialValue;
    }

    /** <b>Internal:</b> not part of the API. */
    public int index() {
        return index;
    }

    @Override
    public String toString() {
        return "shared " + name + " of " + block.name();
    }
}
