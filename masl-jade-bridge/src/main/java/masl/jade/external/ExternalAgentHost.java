package masl.jade.external;

import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import masl.jade.MessagesButTheDfs;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.trust.PendingAnswers;

/**
 * The JADE agent of a MASL agent whose type is answered by an external FIPA agent ({@code <Fipa>}),
 * named after the MASL agent: it hosts the agent's program (a threaded behaviour, as any MASL
 * agent's) and sends the requests of its primitives ({@link FipaBody}). An answer is taken only from
 * the agent asked, with the request's unguessable {@code in-reply-to} ({@link PendingAnswers}); an
 * {@code AGREE} (fipa-request) keeps the request waiting for its result. It answers no request itself.
 */
final class ExternalAgentHost extends Agent {
    private static final long serialVersionUID = 1L;

    private final transient PendingAnswers answers;
    private final transient CountDownLatch ready = new CountDownLatch(1);
    private transient volatile Thread thread;

    ExternalAgentHost(String name) {
        this.answers = new PendingAnswers(name);
    }

    @Override
    protected void setup() {
        thread = Thread.currentThread();
        addBehaviour(new MessagesButTheDfs(this, this::take));
        ready.countDown();
    }

    @Override
    protected void takeDown() {
        answers.failEvery(new IllegalStateException("the mission has ended"));
    }

    /** Waits until the agent has started: true if it has within {@code millis}. */
    boolean awaitStarted(long millis) throws InterruptedException {
        return ready.await(millis, TimeUnit.MILLISECONDS);
    }

    Thread thread() {
        return thread;
    }

    /**
     * Sends {@code request} (one receiver) with a fresh, unguessable {@code reply-with}, which is its
     * conversation id too; the future completes with its answer. Any thread.
     */
    CompletableFuture<ACLMessage> ask(ACLMessage request) {
        CompletableFuture<ACLMessage> answer = answers.register(request);
        request.setConversationId(request.getReplyWith());
        request.setSender(getAID());
        send(request);
        return answer;
    }

    /** Stops waiting for the answer to the request whose {@code reply-with} is {@code replyWith}. */
    void forget(String replyWith, Throwable why) {
        answers.fail(replyWith, why);
    }

    private void take(ACLMessage message) {
        switch (answers.classify(message, getAMS())) {
            case ANSWER -> {
                if (message.getPerformative() != ACLMessage.AGREE) {
                    answers.complete(message);
                }
            }
            case UNDELIVERABLE -> answers.complete(message);
            case NONE -> {
                if (message.getPerformative() != ACLMessage.NOT_UNDERSTOOD) {
                    send(AclInvocations.notUnderstood(message, new ContentException(getLocalName()
                            + " stands for an external agent in a MASL mission and answers no message")));
                }
            }
        }
    }
}
