package masl.jade.placement;

import com.fasterxml.jackson.databind.JsonNode;
import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.lang.reflect.Method;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.Argument;
import masl.jade.acl.ContentException;
import masl.jade.acl.Conversations;
import masl.jade.acl.JsonContent;
import masl.jade.acl.JsonValues;
import masl.jade.acl.Reply;
import masl.jade.stub.BodyStub;
import masl.jade.stub.RemoteFailures;
import masl.runtime.InvocationRefusedException;
import masl.runtime.Journal;

/**
 * The coordinator's side of a body placed in another container: each primitive called on the
 * agent's stub becomes a {@code REQUEST} (conversation {@value Conversations#BODY}, the same
 * JSON content as any FIPA agent's) to the body's JADE agent, and the calling thread waits for the
 * answer: {@code INFORM} gives the result, after the journal text the primitive wrote is appended
 * to the mission's journal; {@code FAILURE} throws a {@link masl.runtime.RemotePrimitiveException}
 * naming the body's exception (the caller perceives {@code uncaught_exception} named after it); {@code REFUSE} throws {@link InvocationRefusedException} (the caller
 * perceives {@code timeout}). Once the body's container is gone, every call throws
 * {@link ContainerGoneException} (the caller perceives {@code uncaught_exception}).
 */
final class RemoteBody implements BodyStub {

    private final String agent;
    private final AID body;
    private final List<Method> methods;
    private final CoordinatorAgent coordinator;
    /** Told of each request sent to the body and answered. */
    private final Runnable roundTrip;
    private volatile Journal journal;

    RemoteBody(String agent, AID body, List<Method> methods, CoordinatorAgent coordinator, Runnable roundTrip) {
        this.agent = agent;
        this.body = body;
        this.methods = List.copyOf(methods);
        this.coordinator = coordinator;
        this.roundTrip = roundTrip;
    }

    /** The mission's journal, once the mission is built: before any primitive is called. */
    void journal(Journal missionJournal) {
        this.journal = missionJournal;
    }

    @Override
    public Object call(int index, Object[] args) {
        Method method = methods.get(index);
        ACLMessage request = AclInvocations.request(body, method.getName(), Arrays.asList(args), null);
        request.setConversationId(Conversations.BODY);
        ACLMessage answer = await(coordinator.ask(request), method);
        roundTrip.run();
        Reply reply;
        try {
            reply = AclInvocations.readReply(answer);
        } catch (ContentException unreadable) {
            throw new IllegalStateException("the body of " + agent + " answered " + method.getName() + " with "
                    + unreadable.describe());
        }
        String written = JsonContent.journalOf(answer.getContent());
        if (!written.isEmpty()) {
            journal.append(written);
        }
        if (reply instanceof Reply.Result result) {
            return method.getReturnType() == void.class ? null : value(result.value(), method);
        }
        if (reply instanceof Reply.Failed failed) {
            throw RemoteFailures.rebuild(failed);
        }
        if (reply instanceof Reply.Refused refused) {
            throw new InvocationRefusedException(method.getName(), refused.reason());
        }
        throw new IllegalStateException("the body of " + agent + " did not understand " + method.getName() + ": "
                + ((Reply.NotUnderstood) reply).error());
    }

    private ACLMessage await(CompletableFuture<ACLMessage> answer, Method method) {
        try {
            return answer.get();
        } catch (InterruptedException missionEnded) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while " + agent + "." + method.getName()
                    + " ran in its container");
        } catch (ExecutionException unanswered) {
            if (unanswered.getCause() instanceof ContainerGoneException gone) {
                throw gone;
            }
            throw new IllegalStateException(unanswered.getCause().getMessage(), unanswered.getCause());
        }
    }

    private Object value(JsonNode node, Method method) {
        try {
            return JsonValues.fromJson(new Argument(node, 1, 1), method.getReturnType(), "the result of "
                    + agent + "." + method.getName());
        } catch (ContentException unusable) {
            throw new IllegalStateException(unusable.getMessage());
        }
    }
}
