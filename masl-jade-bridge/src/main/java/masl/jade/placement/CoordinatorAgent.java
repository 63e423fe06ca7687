package masl.jade.placement;

import jade.core.AID;
import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAException;
import jade.domain.introspection.AMSSubscriber;
import jade.domain.introspection.IntrospectionVocabulary;
import jade.domain.introspection.RemovedContainer;
import jade.lang.acl.ACLMessage;
import java.util.Map;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.function.Consumer;
import masl.jade.DfEntries;
import masl.jade.MessagesButTheDfs;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.acl.Conversations;
import masl.jade.trust.MissionChannel;
import masl.jade.trust.MissionSecret;
import masl.jade.trust.PendingAnswers;

/**
 * {@value Conversations#COORDINATOR}: the agent of the main container through which a mission spanning containers talks
 * to its bodies and their containers. The mission's runtime (every agent's program, entries,
 * barriers, shared variables and labels, events, the watchdog) runs in this JVM; the programs of
 * agents placed elsewhere run in threaded behaviours of this agent, and their primitives are
 * {@code REQUEST}s it sends ({@link RemoteBody}). It takes an answer only from the agent it asked,
 * with the request's unguessable {@code in-reply-to} ({@link PendingAnswers}), and hands over the
 * requests that bodies relay from FIPA agents ({@value Conversations#RELAY}). Every message it sends a party of the
 * mission is signed, and it acts on no answer or relay that is not ({@link MissionChannel}). Registered with the DF as {@value DfEntries#COORDINATOR_SERVICE}.
 */
final class CoordinatorAgent extends Agent {
    private static final long serialVersionUID = 1L;

    private final transient PendingAnswers answers = new PendingAnswers(Conversations.COORDINATOR);
    private final transient MissionChannel channel;
    private final transient Consumer<String> refusals;
    /** Why each agent that can no longer answer (its container is gone) cannot, by local name. */
    private final transient Map<String, String> gone = new ConcurrentHashMap<>();
    private final transient CountDownLatch ready;
    private final transient Consumer<ACLMessage> relays;
    private transient volatile Consumer<ACLMessage> deployed = message -> { };
    private final transient Consumer<String> containerRemoved;
    private final transient Consumer<String> unreachable;
    private transient volatile Thread thread;
    private transient ContainerRemovals removals;

    /**
     * @param secret           signs the messages this agent sends to the mission's parties and checks
     *                         those it takes from them ({@link MissionChannel})
     * @param refusals         told one line for each message claiming to come from a party of the
     *                         mission that is refused (not signed, or a copy), on this agent's thread
     * @param relays           serves a request a body relays (conversation {@value Conversations#RELAY}), on this agent's thread
     * @param containerRemoved told the name of each container the AMS reports removed (its JVM ended or
     *                         died), on this agent's thread
     * @param unreachable      told the local name of an agent a request could not be delivered to (the
     *                         AMS answered {@code FAILURE}), on this agent's thread; it may {@link #abandon} it
     */
    CoordinatorAgent(MissionSecret secret, Consumer<String> refusals, CountDownLatch ready,
            Consumer<ACLMessage> relays, Consumer<String> containerRemoved, Consumer<String> unreachable) {
        this.channel = MissionChannel.of(Conversations.COORDINATOR, secret);
        this.refusals = refusals;
        this.ready = ready;
        this.relays = relays;
        this.containerRemoved = containerRemoved;
        this.unreachable = unreachable;
    }

    @Override
    protected void setup() {
        thread = Thread.currentThread();
        try {
            DFService.register(this, DfEntries.service(getAID(), DfEntries.COORDINATOR_SERVICE, Conversations.COORDINATOR));
        } catch (FIPAException e) {
            // Only a directory entry: the mission does not need it.
        }
        removals = new ContainerRemovals();
        addBehaviour(removals);
        addBehaviour(new MessagesButTheDfs(this, this::take));
        ready.countDown();
    }

    @Override
    protected void takeDown() {
        removals.cancel();
        try {
            DFService.deregister(this);
        } catch (FIPAException e) {
            // The platform is going away with its DF.
        }
        answers.failEvery(new IllegalStateException("the mission's coordinator has ended"));
    }

    Thread thread() {
        return thread;
    }

    /**
     * Sends {@code request} (one receiver) with a fresh, unguessable {@code reply-with}, signed with the
     * mission's secret; the future completes with its answer, which only its receiver can give. May be
     * called from any thread.
     */
    CompletableFuture<ACLMessage> ask(ACLMessage request) {
        CompletableFuture<ACLMessage> answer = answers.register(request);
        String receiver = ((AID) request.getAllReceiver().next()).getLocalName();
        channel.sign(request, getAID());
        String reason = gone.get(receiver);
        if (reason != null) {
            // Checked after registering so that a removal reported meanwhile cannot miss this call.
            answers.fail(request.getReplyWith(), new ContainerGoneException(reason));
        } else {
            send(request);
        }
        return answer;
    }

    /**
     * From now on, requests to {@code receivers} (local names) fail at once, and those waiting for
     * their answer fail now, with a {@link ContainerGoneException} saying why. Any thread.
     */
    void abandon(Map<String, String> reasonByReceiver) {
        gone.putAll(reasonByReceiver);
        answers.failAll(reasonByReceiver, ContainerGoneException::new);
    }

    /**
     * Hands each signed {@value Conversations#DEPLOYED} message to {@code taker}, on this agent's thread, which
     * checks that it comes from the container of the agent it names.
     */
    void deployedTo(Consumer<ACLMessage> taker) {
        this.deployed = taker;
    }

    /**
     * The {@code reply-with} of a coordination message to a container's agent {@code receiver} (local
     * name): the AMS's {@code FAILURE} when it cannot be delivered names it in its {@code in-reply-to},
     * which tells whose container is gone ({@link #deployedReceiver}).
     */
    static String deployedReplyWith(String receiver, long number) {
        return Conversations.DEPLOYED + ">" + receiver + ">" + number;
    }

    /** The receiver a {@link #deployedReplyWith} names; null if {@code replyWith} is none. */
    static String deployedReceiver(String replyWith) {
        if (replyWith == null || !replyWith.startsWith(Conversations.DEPLOYED + ">")) {
            return null;
        }
        int end = replyWith.lastIndexOf('>');
        return end <= Conversations.DEPLOYED.length() ? null : replyWith.substring(Conversations.DEPLOYED.length() + 1, end);
    }

    /** Stops waiting for the answer to {@code request}: one that comes later answers nothing. Any thread. */
    void forget(ACLMessage request) {
        answers.fail(request.getReplyWith(), new CancellationException("no longer waited for"));
    }

    /** Sends {@code message} to its one receiver, a party of the mission, signed, from any thread. */
    void postSigned(ACLMessage message) {
        send(channel.sign(message, getAID()));
    }

    private void take(ACLMessage message) {
        switch (answers.classify(message, getAMS())) {
            case ANSWER -> {
                String refusal = channel.refusal(message);
                if (refusal == null) {
                    answers.complete(message);
                } else {
                    refuse(message, refusal);
                }
            }
            case UNDELIVERABLE -> {
                // Its container is gone, which the AMS's removal event may not have said yet.
                unreachable.accept(answers.receiverOf(message).getLocalName());
                answers.complete(message);
            }
            case NONE -> takeOther(message);
        }
    }

    /** A message that answers none of this agent's requests: a relayed request, or not understood. */
    private void takeOther(ACLMessage message) {
        if (message.getPerformative() == ACLMessage.REQUEST && Conversations.RELAY.equals(message.getConversationId())) {
            String refusal = channel.refusal(message);
            if (refusal == null) {
                relays.accept(message);
            } else {
                refuse(message, refusal);
            }
        } else if (message.getPerformative() == ACLMessage.FAILURE && message.getSender() != null
                && message.getSender().equals(getAMS()) && deployedReceiver(message.getInReplyTo()) != null) {
            // A deployed agent's message its container can no longer take: the container is gone.
            unreachable.accept(deployedReceiver(message.getInReplyTo()));
        } else if (message.getPerformative() == ACLMessage.INFORM && Conversations.DEPLOYED.equals(message.getConversationId())) {
            String refusal = channel.refusal(message);
            if (refusal == null) {
                deployed.accept(message);
            } else {
                refuse(message, refusal);
            }
        } else if (message.getPerformative() != ACLMessage.NOT_UNDERSTOOD
                && !Conversations.ALIVE.equals(message.getConversationId())) {
            send(AclInvocations.notUnderstood(message, new ContentException(
                    "the mission's coordinator answers its bodies and containers only")));
        }
    }

    /**
     * A message claiming to come from a party of the mission (an answer to one of this agent's
     * requests, a relay) that does not prove it: it changes nothing, is said in one line, and its
     * sender is told it was not understood.
     */
    void refuse(ACLMessage message, String reason) {
        refusals.accept("refused " + ACLMessage.getPerformative(message.getPerformative()) + " "
                + message.getConversationId() + " from "
                + (message.getSender() == null ? "no sender" : message.getSender().getName()) + ": " + reason);
        if (message.getPerformative() != ACLMessage.NOT_UNDERSTOOD) {
            send(AclInvocations.notUnderstood(message, new ContentException(reason)));
        }
    }

    /** The AMS's platform events: a container removed, whether it ended or its JVM died. */
    private final class ContainerRemovals extends AMSSubscriber {
        private static final long serialVersionUID = 1L;

        @Override
        @SuppressWarnings({"unchecked", "rawtypes"})
        protected void installHandlers(Map handlers) {
            handlers.put(IntrospectionVocabulary.REMOVEDCONTAINER, (EventHandler) event ->
                    containerRemoved.accept(((RemovedContainer) event).getContainer().getName()));
        }
    }
}
