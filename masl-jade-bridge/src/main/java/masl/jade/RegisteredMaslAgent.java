package masl.jade;

import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.domain.DFService;
import jade.domain.FIPAException;
import java.util.concurrent.CountDownLatch;

/**
 * A JADE agent standing for one MASL agent: registered with the DF under the agent's type and
 * primitives ({@link DfEntries#maslAgent}) while it lives, serving requests with the behaviour its
 * subclass gives. The launcher waits on {@code ready}, then checks {@link #registrationFailure()}.
 */
abstract class RegisteredMaslAgent extends Agent {
    private static final long serialVersionUID = 1L;

    final transient PrimitiveTable primitives;
    private final transient CountDownLatch ready;
    private transient volatile Thread thread;
    private transient volatile FIPAException registrationFailure;

    RegisteredMaslAgent(PrimitiveTable primitives, CountDownLatch ready) {
        this.primitives = primitives;
        this.ready = ready;
    }

    /** The cyclic behaviour that reads this agent's messages. */
    abstract Behaviour requestServer();

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

    /** Why the DF refused the registration, or null if it accepted it. */
    final FIPAException registrationFailure() {
        return registrationFailure;
    }

    /** The agent's own JADE thread (set once it has started). */
    final Thread thread() {
        return thread;
    }
}
