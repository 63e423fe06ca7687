package masl.jade;

import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;

/**
 * {@value #NAME}: the agent of the main container through which a mission spanning containers talks
 * to its bodies and their containers. The mission's runtime (every agent's program, entries,
 * barriers, shared variables and labels, events, the watchdog) runs in this JVM; the programs of
 * agents placed elsewhere run in threaded behaviours of this agent, and their primitives are
 * {@code REQUEST}s it sends ({@link RemoteBody}). It matches answers to requests by
 * {@code in-reply-to}, and hands over the requests that bodies relay from FIPA agents
 * ({@value #RELAY}). Registered with the DF as {@value DfEntries#COORDINATOR_SERVICE}.
 */
final class CoordinatorAgent extends Agent {
    private static final long serialVersionUID = 1L;

    static final String NAME = "masl-coordinator";
    /** The coordinator invoking a primitive on a body. */
    static final String BODY = "masl-body";
    /** The coordinator asking a container to host bodies. */
    static final String PLACE = "masl-place";
    /** The coordinator telling a container that the mission has ended. */
    static final String END = "masl-end";
    /** A body relaying a FIPA agent's request, which the coordinator filters and serves. */
    static final String RELAY = "masl-relay";
    /** A shared event emitted in the mission, sent to the containers hosting bodies. */
    static final String EVENT = "masl-event";

    private final transient Map<String, CompletableFuture<ACLMessage>> pending = new ConcurrentHashMap<>();
    private final transient AtomicLong requests = new AtomicLong();
    private final transient CountDownLatch ready;
    private final transient Consumer<ACLMessage> relays;
    private transient volatile Thread thread;

    /** @param relays serves a request a body relays (conversation {@value #RELAY}), on this agent's thread */
    CoordinatorAgent(CountDownLatch ready, Consumer<ACLMessage> relays) {
        this.ready = ready;
        this.relays = relays;
    }

    @Override
    protected void setup() {
        thread = Thread.currentThread();
        try {
            DFService.register(this, DfEntries.service(getAID(), DfEntries.COORDINATOR_SERVICE, NAME));
        } catch (FIPAException e) {
            // Only a directory entry: the mission does not need it.
        }
        addBehaviour(new MessagesButTheDfs(this, this::take));
        ready.countDown();
    }

    @Override
    protected void takeDown() {
        try {
            DFService.deregister(this);
        } catch (FIPAException e) {
            // The platform is going away with its DF.
        }
        pending.values().forEach(answer -> answer.completeExceptionally(
                new IllegalStateException("the mission's coordinator has ended")));
    }

    Thread thread() {
        return thread;
    }

    /**
     * Sends {@code request} with a fresh {@code reply-with}; the future completes with its answer.
     * May be called from any thread.
     */
    CompletableFuture<ACLMessage> ask(ACLMessage request) {
        String replyWith = NAME + "-" + requests.incrementAndGet();
        request.setReplyWith(replyWith);
        CompletableFuture<ACLMessage> answer = new CompletableFuture<>();
        pending.put(replyWith, answer);
        send(request);
        return answer;
    }

    /** Sends a message from any thread. */
    void post(ACLMessage message) {
        send(message);
    }

    private void take(ACLMessage message) {
        String inReplyTo = message.getInReplyTo();
        CompletableFuture<ACLMessage> waiting = inReplyTo == null ? null : pending.remove(inReplyTo);
        if (waiting != null) {
            waiting.complete(message);
        } else if (message.getPerformative() == ACLMessage.REQUEST && RELAY.equals(message.getConversationId())) {
            relays.accept(message);
        } else if (message.getPerformative() != ACLMessage.NOT_UNDERSTOOD) {
            send(AclInvocations.notUnderstood(message, new ContentException(
                    "the mission's coordinator answers its bodies and containers only")));
        }
    }
}
