package masl.jade;

import masl.jade.acl.Reply;

/**
 * The exception a body's primitive threw, made again in the coordinator's JVM from its class name
 * and message (JSON carries no Java objects): the same class when it is loadable and has a
 * {@code (String)} constructor, so that {@code uncaught_exception} has the same message as
 * in-process; otherwise a {@link RemotePrimitiveException} naming it.
 */
final class RemoteFailures {

    private RemoteFailures() {
    }

    static Throwable rebuild(Reply.Failed failed, ClassLoader classes) {
        try {
            Class<?> type = Class.forName(failed.exception(), false, classes);
            if (Throwable.class.isAssignableFrom(type) && !Error.class.isAssignableFrom(type)) {
                return (Throwable) type.getConstructor(String.class).newInstance(failed.message());
            }
        } catch (ReflectiveOperationException | LinkageError | RuntimeException notRebuilt) {
            // Falls through to the generic form, which still names the class.
        }
        return new RemotePrimitiveException(failed.exception() + ": " + failed.message());
    }

    /** Throws {@code thrown} whatever its kind: a primitive's stub rethrows what the body threw. */
    @SuppressWarnings("unchecked")
    static <E extends Throwable> RuntimeException sneaky(Throwable thrown) throws E {
        throw (E) thrown;
    }

    /** A body's exception whose class this JVM cannot make again. */
    static final class RemotePrimitiveException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        RemotePrimitiveException(String message) {
            super(message);
        }
    }
}
