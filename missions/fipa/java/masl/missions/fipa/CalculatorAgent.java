package masl.missions.fipa;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import jade.core.Agent;
import jade.domain.FIPAAgentManagement.FailureException;
import jade.domain.FIPAAgentManagement.NotUnderstoodException;
import jade.domain.FIPAAgentManagement.RefuseException;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPANames;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import jade.proto.AchieveREResponder;
import java.io.IOException;

/**
 * A plain JADE agent, written the ordinary JADE way: registered with the DF as service "calculator",
 * it answers fipa-request REQUESTs with an AchieveREResponder. Content is JSON
 * ({"primitive": "divide", "args": [12, 4]}): divide is AGREEd, then answered INFORM {"result": …};
 * square is answered INFORM at once (no AGREE); a division by zero is a FAILURE; secret is REFUSEd;
 * ponder is never answered; garbled is answered with a result that is not a number. Knows nothing
 * of MASL.
 */
public class CalculatorAgent extends Agent {
    private static final long serialVersionUID = 1L;
    private static final ObjectMapper JSON = new ObjectMapper();

    @Override
    protected void setup() {
        ServiceDescription service = new ServiceDescription();
        service.setType("calculator");
        service.setName("integer arithmetic");
        service.addProtocols(FIPANames.InteractionProtocol.FIPA_REQUEST);
        service.addLanguages("json");
        service.addOntologies("arithmetic");
        if (!Directory.register(this, service)) {
            doDelete();
            return;
        }
        addBehaviour(new Responder(this));
    }

    @Override
    protected void takeDown() {
        Directory.deregister(this);
    }

    private static final class Responder extends AchieveREResponder {
        private static final long serialVersionUID = 1L;

        Responder(Agent agent) {
            super(agent, MessageTemplate.and(createMessageTemplate(FIPANames.InteractionProtocol.FIPA_REQUEST),
                    MessageTemplate.MatchOntology("arithmetic")));
        }

        @Override
        protected ACLMessage handleRequest(ACLMessage request) throws NotUnderstoodException, RefuseException {
            switch (operation(request)) {
                case "secret" -> throw new RefuseException("not for you");
                case "square", "ponder" -> {
                    // No AGREE: the result (or, for ponder, nothing) follows at once.
                    return null;
                }
                default -> {
                    ACLMessage agree = request.createReply();
                    agree.setPerformative(ACLMessage.AGREE);
                    return agree;
                }
            }
        }

        @Override
        protected ACLMessage prepareResultNotification(ACLMessage request, ACLMessage response) throws FailureException {
            JsonNode content = content(request);
            JsonNode args = content.path("args");
            ACLMessage inform = request.createReply();
            inform.setPerformative(ACLMessage.INFORM);
            switch (content.path("primitive").asText()) {
                case "divide" -> {
                    if (args.get(1).asInt() == 0) {
                        throw new FailureException("division by zero");
                    }
                    inform.setContent("{\"result\":" + args.get(0).asInt() / args.get(1).asInt() + "}");
                }
                case "square" -> inform.setContent("{\"result\":" + args.get(0).asInt() * args.get(0).asInt() + "}");
                case "ponder" -> {
                    // Thinks for ever: no answer at all.
                    return null;
                }
                default -> inform.setContent("{\"result\":\"many\"}");
            }
            return inform;
        }

        private static String operation(ACLMessage request) throws NotUnderstoodException {
            String operation = content(request).path("primitive").asText();
            if (!operation.matches("divide|square|secret|ponder|garbled")) {
                throw new NotUnderstoodException("no operation " + operation);
            }
            return operation;
        }

        private static JsonNode content(ACLMessage request) {
            try {
                return JSON.readTree(request.getContent());
            } catch (IOException e) {
                return JSON.createObjectNode();
            }
        }
    }
}
