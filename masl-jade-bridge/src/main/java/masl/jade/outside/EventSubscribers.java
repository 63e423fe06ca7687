package masl.jade.outside;

import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.Conversations;
import masl.jade.acl.JsonContent;
import masl.runtime.Mission;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * FIPA agents that asked a MASL agent, with a {@code SUBSCRIBE}, for the mission's shared events: each
 * shared event emitted afterwards is sent to them as an {@code INFORM} (conversation
 * {@value Conversations#EVENT}, in reply to the subscription, JSON content
 * {@code {"event": "go", "block": "main", "emitter": "leader", "message": "now"}}) by the agent they
 * subscribed with, until they send it a {@code CANCEL} or the mission ends. One mission; thread-safe.
 *
 * <p>Public for {@link masl.jade.JadeLauncher}, which makes one per mission, and {@code
 * MaslJadeAgent}, which hands it outsiders' subscriptions.
 */
public final class EventSubscribers {

    private final List<String> names;
    private final Map<AID, Subscription> subscriptions = new ConcurrentHashMap<>();
    /** The mission whose events these are: it tells a shared event from a local one, which stays inside. */
    private volatile Mission mission;

    private record Subscription(ACLMessage subscribe, Agent via) {
    }

    /** @param names the mission's agents' names, by proxy id: emitters named in the events sent */
    public EventSubscribers(List<String> names) {
        this.names = List.copyOf(names);
    }

    /** The mission whose events are forwarded, once built: none is before. */
    public void of(Mission built) {
        mission = built;
    }

    /** Takes a {@code SUBSCRIBE} (answered {@code AGREE}) or a {@code CANCEL} that {@code via} received; false for any other message. */
    public boolean take(ACLMessage message, Agent via) {
        if (message.getPerformative() == ACLMessage.SUBSCRIBE) {
            subscriptions.put(message.getSender(), new Subscription(message, via));
            ACLMessage agree = message.createReply();
            agree.setPerformative(ACLMessage.AGREE);
            agree.setSender(via.getAID());
            via.send(agree);
            return true;
        }
        if (message.getPerformative() == ACLMessage.CANCEL) {
            subscriptions.remove(message.getSender());
            return true;
        }
        return false;
    }

    /** {@code trace}, plus each shared event sent to the subscribers. */
    public Trace forwarding(Trace trace) {
        return event -> {
            trace.record(event);
            Mission events = mission;
            if (event instanceof TraceEvent.EventEmitted emitted && emitted.block() != null
                    && !subscriptions.isEmpty() && events != null
                    && events.declaresSharedEvent(emitted.block(), emitted.event())) {
                String emitter = emitted.agent() == Mission.OUTSIDE ? null : names.get(emitted.agent());
                String content = JsonContent.event(emitted.event(), emitted.block(), emitter, emitted.message());
                subscriptions.values().forEach(subscription -> send(subscription, content));
            }
        };
    }

    private static void send(Subscription subscription, String content) {
        ACLMessage inform = subscription.subscribe().createReply();
        inform.setPerformative(ACLMessage.INFORM);
        inform.setConversationId(Conversations.EVENT);
        inform.setLanguage(AclInvocations.LANGUAGE);
        inform.setOntology(AclInvocations.ONTOLOGY);
        inform.setContent(content);
        inform.setSender(subscription.via().getAID());
        subscription.via().send(inform);
    }
}
