package masl.jade;

import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.introspection.AMSSubscriber;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import java.util.function.Consumer;

/**
 * Hands every message an agent receives to {@code taker}, except the DF's and the AMS's platform
 * events: the DF calls the agent makes itself ({@code DFService.register}, {@code search}) and an
 * {@link AMSSubscriber} wait for those in its queue.
 *
 * <p>Public for the agents of {@code placement} and {@code external}, which take their messages the
 * same way.
 */
public final class MessagesButTheDfs extends CyclicBehaviour {
    private static final long serialVersionUID = 1L;

    private final transient MessageTemplate notFromTheDf;
    private final transient Consumer<ACLMessage> taker;

    public MessagesButTheDfs(Agent agent, Consumer<ACLMessage> taker) {
        super(agent);
        this.notFromTheDf = MessageTemplate.not(MessageTemplate.or(MessageTemplate.MatchSender(agent.getDefaultDF()),
                MessageTemplate.or(MessageTemplate.MatchConversationId(AMSSubscriber.PLATFORM_EVENTS),
                        MessageTemplate.MatchConversationId(AMSSubscriber.AMS_SUBSCRIPTION))));
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
