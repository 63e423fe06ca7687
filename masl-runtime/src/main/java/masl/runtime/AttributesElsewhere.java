package masl.runtime;

import java.util.function.Supplier;

/**
 * An agent's implementation object whose attributes are not its own fields: one that stands, in this
 * JVM, for an agent running in another (the JADE bridge's deployed agents). A program's read or write
 * of such an agent's attribute, once its permeability allows it, goes through these methods instead
 * of the code the program hands over ({@code () -> owner.x}), which would read this object's field.
 * Reading another agent's attribute must run where that agent's state is.
 */
public interface AttributesElsewhere {

    /**
     * The value of {@code attribute}; {@code read} is the program's own read of this object's field,
     * which an implementation may run when it is not the program's ({@link AgentContext#readAttribute}).
     */
    Object readAttribute(String attribute, Supplier<?> read);

    /** Writes {@code attribute} as {@code write}, the program's write of this object's field, says. */
    void writeAttribute(String attribute, Runnable write);
}
