package masl.jade.stub;

import masl.jade.acl.Reply;
import masl.runtime.RemotePrimitiveException;

/**
 * The exception a body's primitive threw, made again in the coordinator's JVM from the text of its
 * {@code FAILURE}: a {@link RemotePrimitiveException} carrying the class name and the message, so
 * that {@code uncaught_exception} is named as in-process. No class a message names is ever loaded:
 * a forged {@code FAILURE} could otherwise have any class of the class path initialised.
 *
 * <p>Public for the two kinds of stub: a placed agent's ({@code placement}) and an external agent's
 * ({@code external}).
 */
public final class RemoteFailures {

    private RemoteFailures() {
    }

    public static RemotePrimitiveException rebuild(Reply.Failed failed) {
        return new RemotePrimitiveException(failed.exception(), failed.message());
    }
}
