package masl.jade;

import jade.core.behaviours.Behaviour;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import java.util.concurrent.CountDownLatch;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;

/**
 * The JADE agent of one MASL agent placed in the coordinator's container, named after it. It
 * registers with the DF ({@link DfEntries#maslAgent}), answers invocation requests from any FIPA
 * agent, and hosts the threaded behaviour in which the MASL agent's program runs
 * ({@link ThreadedBehaviourScheduler}).
 *
 * <p>A request is read on this agent's JADE thread: one that is malformed, names an unknown
 * primitive or gives unusable arguments is answered {@code NOT_UNDERSTOOD} at once. A valid one is
 * served as MASL §5 says ({@link Mission#serveOrQueueInvocation}): if the MASL agent is blocked or
 * has finished, at once on this JADE thread, as a plain JADE agent answers; if its program is
 * running, at its next step boundary, on the program's thread. Then it is {@code REFUSE} if the
 * agent's permeability state denies it to an <em>other</em>, else the primitive runs, within the
 * limit of calls from outside the mission ({@link OutsideCalls}), and the answer is {@code INFORM}
 * with its result or {@code FAILURE} with what it threw (or that it ran past the limit).
 */
final class MaslJadeAgent extends RegisteredMaslAgent {
    private static final long serialVersionUID = 1L;

    private final transient int proxyId;
    private final transient AgentImplementation implementation;
    private final transient Mission mission;
    private final transient OutsideCalls outside;

    MaslJadeAgent(int proxyId, AgentImplementation implementation, PrimitiveTable primitives, Mission mission,
            OutsideCalls outside, CountDownLatch ready) {
        super(primitives, ready);
        this.proxyId = proxyId;
        this.implementation = implementation;
        this.mission = mission;
        this.outside = outside;
    }

    @Override
    Behaviour requestServer() {
        return new RequestServer();
    }

    private void serve(ACLMessage message) {
        PrimitiveTable.Call call = requestedCall(message);
        if (call == null) {
            return;
        }
        String primitive = call.primitive().name();
        // A FIPA agent is an "other" (MASL §11): the runtime filters the request by the agent's state
        // when the agent serves it, and runs either the primitive or the refusal.
        mission.serveOrQueueInvocation(proxyId, primitive,
                () -> answer(outside.answer(message, call, implementation, getLocalName())),
                () -> answer(Answers.refusal(message, getLocalName(), primitive)));
    }

    /** Takes every message addressed to this agent. */
    private final class RequestServer extends CyclicBehaviour {
        private static final long serialVersionUID = 1L;

        @Override
        public void action() {
            ACLMessage message = receive();
            if (message == null) {
                block();
            } else {
                serve(message);
            }
        }
    }
}
