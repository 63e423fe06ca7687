package masl.runtime;

import java.util.function.Consumer;

/**
 * A label's store of a result into attribute {@code attribute} of agent {@code owner} (§10,
 * {@code l.b.x = b.m()}), as the translator writes it: {@code write} is the program's field write
 * ({@code value -> owner.x = value}). An owner that stands for an agent running in another JVM
 * ({@link AttributesElsewhere}) has the write go where that agent's state is; any other owner's field
 * is written here. A store checks no permeability, as a label's store never has: the program made the
 * call whose result it stores.
 *
 * @param <T> the attribute's (boxed) type
 */
public final class AttributeStore<T> implements Consumer<T> {

    private final AgentImplementation owner;
    private final String attribute;
    private final Consumer<T> write;

    public AttributeStore(AgentImplementation owner, String attribute, Consumer<T> write) {
        this.owner = owner;
        this.attribute = attribute;
        this.write = write;
    }

    /** The agent whose attribute this stores into. */
    public AgentImplementation owner() {
        return owner;
    }

    /** The name of the attribute this stores into. */
    public String attribute() {
        return attribute;
    }

    /** The program's write of {@code value} into the owner object's field, run by no one yet. */
    public Runnable writing(T value) {
        return () -> write.accept(value);
    }

    @Override
    public void accept(T value) {
        if (owner instanceof AttributesElsewhere elsewhere) {
            elsewhere.writeAttribute(attribute, writing(value));
        } else {
            write.accept(value);
        }
    }
}
