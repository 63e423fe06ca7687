package masl.missions.fipa;

import jade.core.Agent;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * A plain JADE agent with a CyclicBehaviour, speaking plain strings: a REQUEST "greet team" is
 * answered INFORM "hello team". Knows nothing of MASL; MASL finds it by its name, "greeter" (its DF
 * entry, service "greeting", is for others).
 */
public class GreeterAgent extends Agent {
    private static final long serialVersionUID = 1L;

    @Override
    protected void setup() {
        ServiceDescription service = new ServiceDescription();
        service.setType("greeting");
        service.setName("greetings in plain text");
        if (!Directory.register(this, service)) {
            doDelete();
            return;
        }
        addBehaviour(new CyclicBehaviour(this) {
            private static final long serialVersionUID = 1L;

            @Override
            public void action() {
                ACLMessage request = myAgent.receive(MessageTemplate.MatchPerformative(ACLMessage.REQUEST));
                if (request == null) {
                    block();
                    return;
                }
                ACLMessage reply = request.createReply();
                String content = request.getContent() == null ? "" : request.getContent();
                if (content.startsWith("greet ")) {
                    reply.setPerformative(ACLMessage.INFORM);
                    reply.setContent("hello " + content.substring("greet ".length()));
                } else {
                    reply.setPerformative(ACLMessage.NOT_UNDERSTOOD);
                    reply.setContent("I only greet");
                }
                myAgent.send(reply);
            }
        });
    }

    @Override
    protected void takeDown() {
        Directory.deregister(this);
    }
}
