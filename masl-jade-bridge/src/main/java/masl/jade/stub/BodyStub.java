package masl.jade.stub;

import java.util.function.Supplier;

/**
 * Where the primitives of a stub ({@link StubClasses}) go: the stand-in, in the coordinator's JVM,
 * for an agent whose body lives in another container. Public only because generated classes,
 * defined in a class loader of their own, must reach it.
 */
public interface BodyStub {

    /**
     * Runs primitive number {@code method} (in the order the stub class was made with) with
     * {@code args} (primitive values boxed) on the body, and returns its result, boxed, or
     * {@code null} for {@code void}; throws what the body's primitive threw.
     */
    Object call(int method, Object[] args);

    /**
     * The value of the agent's {@code attribute}, which the runtime reads through the stub
     * ({@link masl.runtime.AttributesElsewhere}): by default the stub's own field, as {@code read}
     * (the program's code) reads it.
     */
    default Object readAttribute(String attribute, Supplier<?> read) {
        return read.get();
    }

    /** Writes the agent's {@code attribute} as {@code write} says: by default the stub's own field. */
    default void writeAttribute(String attribute, Runnable write) {
        write.run();
    }
}
