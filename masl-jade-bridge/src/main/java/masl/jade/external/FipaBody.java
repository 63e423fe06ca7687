package masl.jade.external;

import jade.core.AID;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import java.lang.reflect.Method;
import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.function.Consumer;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.acl.ForeignContent;
import masl.jade.acl.JsonContent;
import masl.jade.acl.Reply;
import masl.jade.stub.BodyStub;
import masl.jade.stub.RemoteFailures;
import masl.runtime.InvocationRefusedException;
import masl.runtime.RemotePrimitiveException;
import masl.runtime.descriptor.FipaBinding;

/**
 * Where the primitives of an agent answered by an external FIPA agent go: each is a {@code REQUEST}
 * (protocol fipa-request, the descriptor's language and ontology) from the agent's
 * {@link ExternalAgentHost} to that FIPA agent, and the calling thread waits, up to the call limit, for
 * the answer. {@code AGREE} keeps it waiting; {@code INFORM} gives the result, converted to the
 * primitive's return type (content that cannot be is a positioned error: one line to the problems,
 * and the caller perceives {@code uncaught_exception}); {@code FAILURE} throws a
 * {@link RemotePrimitiveException} ({@code uncaught_exception}); {@code REFUSE}, {@code NOT_UNDERSTOOD},
 * any other answer and no answer within the limit throw {@link InvocationRefusedException}
 * ({@code timeout}).
 */
final class FipaBody implements BodyStub {

    /** The class name {@code uncaught_exception} gives for a {@code FAILURE} not in MASL's JSON form. */
    static final String FAILURE = "FAILURE";

    private final String agent;
    private final FipaBinding binding;
    private final List<Method> methods;
    private final ExternalAgentHost host;
    private final Duration limit;
    private final Consumer<String> problems;
    private volatile AID peer;

    FipaBody(String agent, FipaBinding binding, List<Method> methods, ExternalAgentHost host, Duration limit,
            Consumer<String> problems) {
        this.agent = agent;
        this.binding = binding;
        this.methods = List.copyOf(methods);
        this.host = host;
        this.limit = limit;
        this.problems = problems;
    }

    @Override
    public Object call(int index, Object[] args) {
        Method method = methods.get(index);
        ACLMessage request = request(method.getName(), Arrays.asList(args));
        ACLMessage answer = await(host.ask(request), request.getReplyWith(), method.getName());
        String primitive = agent + "." + method.getName();
        switch (answer.getPerformative()) {
            case ACLMessage.INFORM -> {
                return method.getReturnType() == void.class ? null : result(answer, method, primitive);
            }
            case ACLMessage.FAILURE -> throw failure(answer.getContent());
            default -> throw new InvocationRefusedException(method.getName(), peer.getName() + " answered "
                    + ACLMessage.getPerformative(answer.getPerformative()) + " to " + primitive + ": "
                    + answer.getContent());
        }
    }

    /** The FIPA agent found for this agent: set before the mission starts. */
    void peer(AID found) {
        this.peer = found;
    }

    private ACLMessage request(String primitive, List<Object> args) {
        ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
        request.addReceiver(peer);
        request.setProtocol(FIPANames.InteractionProtocol.FIPA_REQUEST);
        if (FipaBinding.JSON.equals(binding.language())) {
            request.setLanguage(AclInvocations.LANGUAGE);
        }
        if (binding.ontology() != null) {
            request.setOntology(binding.ontology());
        }
        request.setContent(ForeignContent.request(binding.language(), primitive, args));
        return request;
    }

    private ACLMessage await(CompletableFuture<ACLMessage> answer, String replyWith, String primitive) {
        try {
            return answer.get(limit.toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException silent) {
            host.forget(replyWith, silent);
            throw new InvocationRefusedException(primitive, peer.getName() + " did not answer " + agent + "."
                    + primitive + " within " + limit.toMillis() + " ms");
        } catch (InterruptedException missionEnded) {
            Thread.currentThread().interrupt();
            host.forget(replyWith, missionEnded);
            throw new IllegalStateException("interrupted while " + peer.getName() + " ran " + agent + "." + primitive);
        } catch (ExecutionException unanswered) {
            throw new IllegalStateException(unanswered.getCause().getMessage(), unanswered.getCause());
        }
    }

    private Object result(ACLMessage answer, Method method, String primitive) {
        try {
            return ForeignContent.result(binding.language(), answer.getContent(), method.getReturnType(),
                    "the result of " + primitive);
        } catch (ContentException unusable) {
            String problem = "the INFORM of " + peer.getName() + " to " + primitive + ": " + unusable.describe();
            problems.accept(problem);
            throw new IllegalStateException(problem);
        }
    }

    /** MASL's own failure content names the exception; any other content is the message of a plain {@value #FAILURE}. */
    private RemotePrimitiveException failure(String content) {
        if (FipaBinding.JSON.equals(binding.language())) {
            try {
                if (JsonContent.parseReply(Reply.Kind.FAILED, content) instanceof Reply.Failed failed) {
                    return RemoteFailures.rebuild(failed);
                }
            } catch (ContentException notMasls) {
                // A FIPA agent's own wording: kept as the message.
            }
        }
        return new RemotePrimitiveException(FAILURE, content);
    }
}
