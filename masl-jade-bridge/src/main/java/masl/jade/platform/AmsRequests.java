package masl.jade.platform;

import jade.content.AgentAction;
import jade.content.ContentManager;
import jade.content.lang.Codec;
import jade.content.lang.sl.SLCodec;
import jade.content.onto.OntologyException;
import jade.content.onto.basic.Action;
import jade.core.Agent;
import jade.domain.FIPANames;
import jade.domain.JADEAgentManagement.JADEManagementOntology;
import jade.lang.acl.ACLMessage;

/**
 * Requests to the platform's AMS in JADE's management ontology and FIPA-SL, as JADE's own tools send
 * them ({@code ShutdownPlatform}, {@code QueryPlatformLocationsAction}, …).
 */
final class AmsRequests {

    private AmsRequests() {
    }

    /**
     * The {@code REQUEST} asking {@code agent}'s AMS to perform {@code action}; registers the language
     * and ontology with the agent's content manager, which then also reads the AMS's answer.
     */
    static ACLMessage request(Agent agent, AgentAction action) {
        ContentManager content = agent.getContentManager();
        content.registerLanguage(new SLCodec(), FIPANames.ContentLanguage.FIPA_SL);
        content.registerOntology(JADEManagementOntology.getInstance());
        ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
        request.addReceiver(agent.getAMS());
        request.setLanguage(FIPANames.ContentLanguage.FIPA_SL);
        request.setOntology(JADEManagementOntology.NAME);
        try {
            content.fillContent(request, new Action(agent.getAMS(), action));
        } catch (Codec.CodecException | OntologyException e) {
            throw new IllegalStateException("JADE cannot encode its own " + action.getClass().getSimpleName(), e);
        }
        return request;
    }
}
