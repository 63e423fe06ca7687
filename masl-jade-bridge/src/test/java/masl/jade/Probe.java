package masl.jade;

import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

/**
 * A plain FIPA agent written with the JADE API only, driven by a test: it sends what the test gives
 * it and queues every message it receives, but the DF's and the AMS's, for the test to take. The
 * test may also use it for DF searches ({@code DFService}), from its own thread.
 */
public final class Probe extends Agent {
    private static final long serialVersionUID = 1L;

    private final transient BlockingQueue<ACLMessage> received = new LinkedBlockingQueue<>();

    @Override
    protected void setup() {
        addBehaviour(new CyclicBehaviour(this) {
            private static final long serialVersionUID = 1L;

            /** The DF's and AMS's answers are left to the JADE calls that wait for them. */
            private final MessageTemplate notFromThePlatform = MessageTemplate.not(MessageTemplate.or(
                    MessageTemplate.MatchSender(getDefaultDF()), MessageTemplate.MatchSender(getAMS())));

            @Override
            public void action() {
                ACLMessage message = myAgent.receive(notFromThePlatform);
                if (message == null) {
                    block();
                } else {
                    received.add(message);
                }
            }
        });
    }

    /** Sends {@code message} from this agent (JADE's {@code send} may be called from any thread). */
    public void sendMessage(ACLMessage message) {
        send(message);
    }

    /** The next message received, waiting up to 20 s for it; fails the test if none comes. */
    public ACLMessage next() throws InterruptedException {
        ACLMessage message = received.poll(20, TimeUnit.SECONDS);
        if (message == null) {
            throw new AssertionError(getLocalName() + " received no message within 20 s");
        }
        return message;
    }
}
