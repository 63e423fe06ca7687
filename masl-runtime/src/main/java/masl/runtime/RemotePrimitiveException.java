package masl.runtime;

/**
 * What a primitive threw in another JVM (the body of an agent placed in another JADE container),
 * made again here from text: the remote exception's class name and message, never by loading the
 * class a message names (a forged answer could name any class of the class path, and loading it runs
 * its static initialiser). The caller perceives {@code uncaught_exception} with the remote class
 * name as its message, as if the primitive had thrown here.
 */
public class RemotePrimitiveException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final String remoteClassName;

    public RemotePrimitiveException(String remoteClassName, String message) {
        super(message, null, false, false);
        this.remoteClassName = remoteClassName;
    }

    /** The fully qualified name of the class of the exception thrown remotely, as its JVM gave it. */
    public String remoteClassName() {
        return remoteClassName;
    }

    /**
     * The class name a MASL program sees for {@code thrown} ({@code uncaught_exception}'s message): the
     * remote class's for a remote exception, else the class's own.
     */
    public static String classNameOf(Throwable thrown) {
        return thrown instanceof RemotePrimitiveException remote ? remote.remoteClassName : thrown.getClass().getName();
    }

    @Override
    public String toString() {
        String message = getMessage();
        return message == null ? remoteClassName : remoteClassName + ": " + message;
    }
}
