package masl.jade;

import jade.core.behaviours.Behaviour;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import java.util.concurrent.CountDownLatch;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.acl.Conversations;
import masl.jade.acl.EventContent;
import masl.jade.outside.AttributeQueries;
import masl.jade.outside.EventSubscribers;
import masl.jade.outside.OutsideCalls;
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
 * with its result or {@code FAILURE} with what it threw (or that it ran past the limit). A
 * {@code SUBSCRIBE} subscribes its sender to the mission's shared events, a {@code CANCEL} ends that
 * ({@link EventSubscribers}); an {@code INFORM} of conversation {@value Conversations#EVENT}
 * raises the shared event it names ({@link EventContent}); a {@code QUERY_REF} reads an attribute
 * ({@link AttributeQueries}).
 */
final class MaslJadeAgent extends RegisteredMaslAgent {
    private static final long serialVersionUID = 1L;

    private final transient int proxyId;
    private final transient AgentImplementation implementation;
    private final transient Mission mission;
    private final transient OutsideCalls outside;
    private final transient EventSubscribers subscribers;

    MaslJadeAgent(int proxyId, AgentImplementation implementation, PrimitiveTable primitives, Mission mission,
            OutsideCalls outside, EventSubscribers subscribers, CountDownLatch ready) {
        super(primitives, ready);
        this.proxyId = proxyId;
        this.implementation = implementation;
        this.mission = mission;
        this.outside = outside;
        this.subscribers = subscribers;
    }

    @Override
    protected Behaviour requestServer() {
        return new RequestServer();
    }

    private void serve(ACLMessage message) {
        if (subscribers.take(message, this)) {
            return;
        }
        if (message.getPerformative() == ACLMessage.INFORM && Conversations.EVENT.equals(message.getConversationId())) {
            raise(message);
            return;
        }
        if (message.getPerformative() == ACLMessage.QUERY_REF) {
            answer(AttributeQueries.answer(message, mission, proxyId, table(), implementation, getLocalName()));
            return;
        }
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

    /** A FIPA agent raising a shared event of the mission; answered only when it cannot be raised. */
    private void raise(ACLMessage message) {
        try {
            EventContent event = EventContent.parse(message.getContent());
            if (mission.emitFromOutside(event.event(), event.message()) == 0) {
                answer(AclInvocations.notUnderstood(message, new ContentException("no agent of the mission"
                        + " perceives a shared event named " + event.event() + " now")));
            }
        } catch (ContentException problem) {
            answer(AclInvocations.notUnderstood(message, problem));
        }
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
