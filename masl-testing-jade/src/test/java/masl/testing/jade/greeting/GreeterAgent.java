package masl.testing.jade.greeting;

import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;

/**
 * A plain JADE agent that knows nothing of MASL: a REQUEST "greet team" is answered INFORM "hello
 * team, from JADE" (not what the stand-in says, so that a journal tells who answered).
 */
public class GreeterAgent extends Agent {
    private static final long serialVersionUID = 1L;

    @Override
    protected void setup() {
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
                reply.setPerformative(ACLMessage.INFORM);
                reply.setContent("hello " + request.getContent().substring("greet ".length()) + ", from JADE");
                myAgent.send(reply);
            }
        });
    }
}
