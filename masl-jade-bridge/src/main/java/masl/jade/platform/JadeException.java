package masl.jade.platform;

/** A JADE platform or container could not be started, joined or used; the message says why. */
public final class JadeException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public JadeException(String message) {
        super(message);
    }

    public JadeException(String message, Throwable cause) {
        super(message, cause);
    }
}
