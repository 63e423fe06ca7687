package masl.jade.placement;

/**
 * A call to the body of an agent placed in a container that is no longer in the platform (its JVM
 * ended or died): the calling agent perceives {@code uncaught_exception} with this class's name.
 */
public final class ContainerGoneException extends IllegalStateException {
    private static final long serialVersionUID = 1L;

    public ContainerGoneException(String message) {
        super(message);
    }
}
