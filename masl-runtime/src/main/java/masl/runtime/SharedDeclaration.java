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
    private final Class<T> type;

    SharedDeclaration(EntryDefinition block, String name, int index, T initialValue, Class<T> type) {
        this.block = block;
        this.name = name;
        this.index = index;
        this.initialValue = initialValue;
        this.type = type;
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

    /** The array type of a variable that holds an array ({@link EntryDefinition#declareSharedArray}); null for others. */
    public Class<T> arrayType() {
        return type;
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
