package masl.jade;

import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.domain.DFService;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import java.util.concurrent.CountDownLatch;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;

/**
 * A JADE agent standing for one MASL agent: registered with the DF under the agent's type and
 * primitives ({@link DfEntries#maslAgent}) while it lives, serving requests with the behaviour its
 * subclass gives. The launcher waits on {@code ready}, then checks {@link #registrationFailure()}.
 *
 * <p>Public for the bodies of placed agents ({@code placement}), the other kind of registered agent;
 * {@link #registrationFailure} and {@link #thread} are public for the container that creates and
 * ends them.
 */
public abstract class RegisteredMaslAgent extends Agent {
    private static final long serialVersionUID = 1L;

    private final transient PrimitiveTable primitives;
    private final transient CountDownLatch ready;
    private transient volatile Thread thread;
    private transient volatile FIPAException registrationFailure;

    public RegisteredMaslAgent(PrimitiveTable primitives, CountDownLatch ready) {
        this.primitives = primitives;
        this.ready = ready;
    }

    /** The agent's type's primitives, bound to its implementation. */
    protected final PrimitiveTable table() {
        return primitives;
    }

    /** The cyclic behaviour that reads this agent's messages. */
    protected abstract Behaviour requestServer();

    @Override
    protected final void setup() {
        thread = Thread.currentThread();
        try {
            DFService.register(this, DfEntries.maslAgent(getAID(), primitives));
        } catch (FIPAException e) {
            registrationFailure = e;
        }
        addBehaviour(requestServer());
        ready.countDown();
    }

    @Override
    protected final void takeDown() {
        if (registrationFailure == null) {
            try {
                DFService.deregister(this);
            } catch (FIPAException e) {
                // The platform is going away with its DF: nothing is left to deregister from.
            }
        }
    }

    /**
     * The primitive call a request asks for, or null when there is none to serve: a
     * {@code NOT_UNDERSTOOD} is never answered (two agents would echo each other forever), and a
     * malformed request, an unknown primitive or unusable arguments are answered
     * {@code NOT_UNDERSTOOD} here.
     */
    protected final PrimitiveTable.Call requestedCall(ACLMessage message) {
        if (message.getPerformative() == ACLMessage.NOT_UNDERSTOOD) {
            return null;
        }
        try {
            return primitives.bind(AclInvocations.readRequest(message));
        } catch (ContentException problem) {
            answer(AclInvocations.notUnderstood(message, problem));
            return null;
        }
    }

    /**
     * Sends an answer with this agent as its sender, set here: JADE's {@code send} finds a missing
     * sender by catching a {@code NullPointerException}, a cost on every answer otherwise.
     */
    protected final void answer(ACLMessage reply) {
        reply.setSender(getAID());
        send(reply);
    }

    /** Why the DF refused the registration, or null if it accepted it. */
    public final FIPAException registrationFailure() {
        return registrationFailure;
    }

    /** The agent's own JADE thread (set once it has started). */
    public final Thread thread() {
        return thread;
    }
}
