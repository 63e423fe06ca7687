package masl.runtime;

/**
 * Thrown by a primitive's Java code when the agent that was to run it refused to (the body of an
 * agent placed in another JADE container answered {@code REFUSE}): the caller perceives
 * {@code timeout}, as for a denial by permeability (§11), not {@code uncaught_exception}.
 */
public class InvocationRefusedException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final String primitive;

    public InvocationRefusedException(String primitive, String reason) {
        super(reason);
        this.primitive = primitive;
    }

    /** The refused primitive's name: {@code timeout}'s message. */
    public String primitive() {
        return primitive;
    }
}
