package masl.jade;

import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import java.util.function.Consumer;

/**
 * Hands every message an agent receives to {@code taker}, except the DF's: the DF calls the agent
 * makes itself ({@code DFService.register}, {@code search}) wait for those in its queue.
 */
final class MessagesButTheDfs extends CyclicBehaviour {
    private static final long serialVersionUID = 1L;

    private final transient MessageTemplate notFromTheDf;
    private final transient Consumer<ACLMessage> taker;

    MessagesButTheDfs(Agent agent, Consumer<ACLMessage> taker) {
        super(agent);
        this.notFromTheDf = MessageTemplate.not(MessageTemplate.MatchSender(agent.getDefaultDF()));
        this.taker = taker;
    }

    @Override
    public void action() {
        ACLMessage message = myAgent.receive(notFromTheDf);
        if (message == null) {
            block();
        } else {
            taker.accept(message);
        }
    }
}
