package masl.jade.placement;

import jade.core.AID;
import jade.core.behaviours.Behaviour;
import jade.lang.acl.ACLMessage;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.RejectedExecutionException;
import masl.jade.Answers;
import masl.jade.MessagesButTheDfs;
import masl.jade.PrimitiveTable;
import masl.jade.RegisteredMaslAgent;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.Conversations;
import masl.jade.acl.JsonContent;
import masl.jade.acl.Reply;
import masl.jade.trust.MissionChannel;
import masl.jade.trust.UnguessableIds;
import masl.runtime.AgentImplementation;

/**
 * The body of a MASL agent placed in a container away from the coordinator: a JADE agent named
 * after the MASL agent, registered with the DF like any MASL agent, holding the implementation
 * object whose primitives run here. The agent's program runs in the coordinator's JVM.
 *
 * <ul>
 * <li>A request from the coordinator, signed with the mission's secret ({@link MissionChannel}), runs
 * its primitive on a thread of the container's pool (so a primitive that blocks holds no JADE
 * thread) and is answered with the result, or the exception, and the journal text it wrote
 * ({@link BodyJournal}), signed: the coordinator takes no answer that is not.
 * <li>A request from any other FIPA agent (or one merely claiming to be the coordinator) is read
 * here ({@code NOT_UNDERSTOOD} at once if malformed), then relayed to the coordinator ({@value Conversations#RELAY}), which filters it
 * by the agent's permeability state as an <em>other</em> when the agent serves it, as in-process,
 * and has it run here; its answer goes back to the requester with the requester's
 * {@code in-reply-to}.
 * </ul>
 */
final class BodyAgent extends RegisteredMaslAgent {
    private static final long serialVersionUID = 1L;

    private final transient AgentImplementation implementation;
    private final transient BodyJournal journal;
    private final transient AID coordinator;
    private final transient MissionChannel channel;
    private final transient ExecutorService primitiveThreads;
    private final transient Map<String, ACLMessage> relayed = new ConcurrentHashMap<>();

    BodyAgent(AgentImplementation implementation, BodyJournal journal, PrimitiveTable primitives, AID coordinator,
            MissionChannel channel, ExecutorService primitiveThreads, CountDownLatch ready) {
        super(primitives, ready);
        this.implementation = implementation;
        this.journal = journal;
        this.coordinator = coordinator;
        this.channel = channel;
        this.primitiveThreads = primitiveThreads;
    }

    @Override
    protected Behaviour requestServer() {
        return new MessagesButTheDfs(this, this::take);
    }

    private void take(ACLMessage message) {
        boolean fromCoordinator = coordinator.equals(message.getSender());
        if (fromCoordinator && message.getInReplyTo() != null && relayed.containsKey(message.getInReplyTo())) {
            if (channel.refusal(message) == null) {
                answer(forwarded(relayed.remove(message.getInReplyTo()), message));
            }
            return;
        }
        PrimitiveTable.Call call = requestedCall(message);
        if (call == null) {
            return;
        }
        if (fromCoordinator && channel.refusal(message) == null) {
            serve(message, call);
        } else {
            relay(message);
        }
    }

    /** Runs the coordinator's request on a pool thread; the answer, signed, carries the journal text written. */
    private void serve(ACLMessage request, PrimitiveTable.Call call) {
        try {
            primitiveThreads.execute(() -> answer(channel.sign(journal.collecting(
                    written -> Answers.run(request, call, implementation, written)), getAID())));
        } catch (RejectedExecutionException missionEnded) {
            send(channel.sign(AclInvocations.reply(request, Reply.Kind.REFUSED,
                    JsonContent.refusal(getLocalName() + " no longer serves: its mission has ended")), getAID()));
        }
    }

    private void relay(ACLMessage request) {
        ACLMessage relay = new ACLMessage(ACLMessage.REQUEST);
        relay.addReceiver(coordinator);
        relay.setConversationId(Conversations.RELAY);
        relay.setLanguage(AclInvocations.LANGUAGE);
        relay.setOntology(AclInvocations.ONTOLOGY);
        relay.setContent(request.getContent());
        String replyWith = UnguessableIds.next(getLocalName() + "-relay");
        relay.setReplyWith(replyWith);
        relayed.put(replyWith, request);
        send(channel.sign(relay, getAID()));
    }

    /** The coordinator's answer to a relayed request, as the answer of this agent to its requester. */
    private static ACLMessage forwarded(ACLMessage request, ACLMessage answer) {
        ACLMessage reply = request.createReply();
        reply.setPerformative(answer.getPerformative());
        reply.setLanguage(AclInvocations.LANGUAGE);
        reply.setOntology(AclInvocations.ONTOLOGY);
        reply.setContent(answer.getContent());
        return reply;
    }
}
