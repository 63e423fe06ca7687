package masl.jade.trust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.util.concurrent.CompletableFuture;
import masl.jade.Detonator;
import masl.jade.acl.Reply;
import masl.jade.stub.RemoteFailures;
import masl.runtime.RemotePrimitiveException;
import org.junit.jupiter.api.Test;

/**
 * The coordinator takes an answer only from the agent it asked, with the request's unguessable
 * conversation id; a body's failure is rebuilt from text, never by loading the class it names.
 */
class PendingAnswersTest {

    private static final AID BODY = new AID("b@platform", AID.ISGUID);
    private static final AID AMS = new AID("ams@platform", AID.ISGUID);
    private static final AID FORGER = new AID("forger@platform", AID.ISGUID);

    private final PendingAnswers answers = new PendingAnswers("masl-coordinator");

    @Test
    void theRightIdFromAnotherAgentIsNoAnswer() {
        ACLMessage request = request();
        CompletableFuture<ACLMessage> answer = answers.register(request);
        ACLMessage forged = reply(request, FORGER, ACLMessage.INFORM);
        assertEquals(PendingAnswers.Taken.NONE, answers.classify(forged, AMS));
        ACLMessage real = reply(request, BODY, ACLMessage.INFORM);
        assertEquals(PendingAnswers.Taken.ANSWER, answers.classify(real, AMS));
        answers.complete(real);
        assertSame(real, answer.getNow(null));
    }

    @Test
    void onlyTheAmsReportsARequestUndeliverable() {
        ACLMessage request = request();
        answers.register(request);
        assertEquals(PendingAnswers.Taken.UNDELIVERABLE, answers.classify(reply(request, AMS, ACLMessage.FAILURE), AMS));
        assertEquals(PendingAnswers.Taken.NONE, answers.classify(reply(request, AMS, ACLMessage.INFORM), AMS));
        assertEquals(PendingAnswers.Taken.NONE, answers.classify(reply(request, FORGER, ACLMessage.FAILURE), AMS));
        assertEquals(BODY, answers.receiverOf(reply(request, FORGER, ACLMessage.FAILURE)));
    }

    @Test
    void idsAreFreshAndUnguessable() {
        ACLMessage first = request();
        ACLMessage second = request();
        answers.register(first);
        answers.register(second);
        assertNotEquals(first.getReplyWith(), second.getReplyWith());
        assertTrue(first.getReplyWith().matches("masl-coordinator-[A-Za-z0-9_-]{22}"), first.getReplyWith());
        ACLMessage guess = new ACLMessage(ACLMessage.INFORM);
        guess.setSender(BODY);
        guess.setInReplyTo("masl-coordinator-1");
        assertEquals(PendingAnswers.Taken.NONE, answers.classify(guess, AMS));
    }

    @Test
    void anAnswerCompletesItsRequestOnce() {
        ACLMessage request = request();
        CompletableFuture<ACLMessage> answer = answers.register(request);
        ACLMessage real = reply(request, BODY, ACLMessage.INFORM);
        answers.complete(real);
        assertEquals(PendingAnswers.Taken.NONE, answers.classify(reply(request, BODY, ACLMessage.INFORM), AMS),
                "a replay of an answered conversation");
        assertNull(answers.receiverOf(real));
        assertTrue(answer.isDone());
    }

    @Test
    void aFailureIsRebuiltFromTextWithoutLoadingTheClassItNames() {
        RemotePrimitiveException rebuilt = RemoteFailures.rebuild(new Reply.Failed(Detonator.class.getName(), "boom"));
        assertEquals(Detonator.class.getName(), rebuilt.remoteClassName());
        assertEquals("boom", rebuilt.getMessage());
        assertNull(System.getProperty(Detonator.MARK), "the class the failure named was initialised");
        assertEquals(Detonator.class.getName(), RemotePrimitiveException.classNameOf(rebuilt));
    }

    private static ACLMessage request() {
        ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
        request.addReceiver(BODY);
        return request;
    }

    private static ACLMessage reply(ACLMessage request, AID sender, int performative) {
        ACLMessage reply = new ACLMessage(performative);
        reply.setSender(sender);
        reply.setInReplyTo(request.getReplyWith());
        return reply;
    }
}
