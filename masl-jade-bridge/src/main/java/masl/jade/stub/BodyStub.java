package masl.jade.stub;

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
}
