package masl.jade;

import jade.lang.acl.ACLMessage;
import java.lang.reflect.InvocationTargetException;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.JsonContent;
import masl.jade.acl.Reply;
import masl.runtime.AgentImplementation;

/**
 * Runs a request's primitive and makes its answer: {@code INFORM} with the result, or {@code FAILURE}.
 *
 * <p>Public for the bodies of placed agents ({@code placement}) and the calls from outside ({@code
 * outside}), which answer requests the same way.
 */
public final class Answers {

    private Answers() {
    }

    /**
     * Runs {@code call} on {@code target} and answers {@code request}. With {@code journal} (a body
     * answering the coordinator), the answer also carries the journal text the primitive wrote,
     * read once it has returned; without, it is the plain answer any FIPA agent gets.
     */
    public static ACLMessage run(ACLMessage request, PrimitiveTable.Call call, AgentImplementation target,
            CharSequence journal) {
        Object result;
        try {
            result = call.invoke(target);
        } catch (InvocationTargetException thrown) {
            return AclInvocations.reply(request, Reply.Kind.FAILED, journal == null
                    ? JsonContent.failure(thrown.getCause())
                    : JsonContent.failure(thrown.getCause(), journal.toString()));
        }
        try {
            return AclInvocations.reply(request, Reply.Kind.RESULT, journal == null
                    ? JsonContent.result(result) : JsonContent.result(result, journal.toString()));
        } catch (RuntimeException | StackOverflowError unwritable) {
            // A result whose toString throws, or a collection holding itself: the requester's
            // failure, not the mission's.
            return AclInvocations.reply(request, Reply.Kind.FAILED, journal == null
                    ? JsonContent.failure(unwritable) : JsonContent.failure(unwritable, journal.toString()));
        }
    }

    /** The {@code REFUSE} of a request that the permeability of {@code agent} denies to others. */
    public static ACLMessage refusal(ACLMessage request, String agent, String primitive) {
        return AclInvocations.reply(request, Reply.Kind.REFUSED,
                JsonContent.refusal("the permeability of " + agent + " denies others invoking " + primitive));
    }
}
