package masl.jade.acl;

import jade.core.AID;
import jade.lang.acl.ACLMessage;

/**
 * The conversations between the parties of a mission spanning containers (its coordinator, each
 * container's agent, each body) and the names those parties have on the platform: the protocol the
 * bridge's packages share, and what a FIPA agent watching the platform sees. Every message of these
 * conversations is signed and checked ({@code masl.jade.trust.MissionChannel}).
 */
public final class Conversations {

    /** The local name of the coordinator of a mission spanning containers: one per platform. */
    public static final String COORDINATOR = "masl-coordinator";
    /** The coordinator invoking a primitive on a body. */
    public static final String BODY = "masl-body";
    /** The coordinator asking a container to host bodies. */
    public static final String PLACE = "masl-place";
    /** The coordinator telling a container that the mission has ended. */
    public static final String END = "masl-end";
    /** A body relaying a FIPA agent's request, which the coordinator filters and serves. */
    public static final String RELAY = "masl-relay";
    /** A shared event emitted in the mission, sent to the containers hosting bodies. */
    public static final String EVENT = "masl-event";
    /** The coordination of a deployed agent's program with its mission, both ways ({@code INFORM}s). */
    public static final String DEPLOYED = "masl-deployed";
    /**
     * A container's checks that its coordinator (before a placement: the AMS) is still there:
     * {@code INFORM}s nobody answers, but the MTS when undeliverable; and the coordinator's
     * {@code REQUEST}s asking whether a container is still there, which it answers {@code INFORM}.
     */
    public static final String ALIVE = "masl-alive";

    private Conversations() {
    }

    /** The local name of the agent of container {@code container}, which hosts the bodies placed there. */
    public static String containerAgent(String container) {
        return "masl-container-" + container;
    }

    /** A {@code REQUEST} of {@code conversation} to {@code receiver}, in language json and ontology masl. */
    public static ACLMessage request(AID receiver, String conversation, String content) {
        ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
        request.addReceiver(receiver);
        request.setConversationId(conversation);
        request.setLanguage(AclInvocations.LANGUAGE);
        request.setOntology(AclInvocations.ONTOLOGY);
        request.setContent(content);
        return request;
    }

    /** An {@code INFORM} of {@code conversation} to {@code receiver}, in language json and ontology masl. */
    public static ACLMessage inform(AID receiver, String conversation, String content) {
        ACLMessage inform = request(receiver, conversation, content);
        inform.setPerformative(ACLMessage.INFORM);
        return inform;
    }
}
