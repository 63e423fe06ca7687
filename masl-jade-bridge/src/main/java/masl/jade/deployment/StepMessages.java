package masl.jade.deployment;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import masl.runtime.AgentContext;
import masl.runtime.DeployedPrograms;

/**
 * The messages of a deployed agent's step for its stand-in (requests, the step's end), in the order
 * they came, which the agent's slices take one at a time. A slice that finds none parks the agent
 * without a thread ({@link #awaitElsewhere}), and the next message lets it run again, on the thread
 * that brings it; a thread that must wait for the next message waits for its {@link #arrival}.
 *
 * <p><b>Memory consistency effects.</b> Actions of a thread before it {@linkplain #add adds} a
 * message happen-before the actions of the slice that {@linkplain #poll takes} it, and of whoever
 * the arrival it completes runs.
 */
final class StepMessages {

    private final ConcurrentLinkedQueue<ObjectNode> messages = new ConcurrentLinkedQueue<>();
    /** The arrival a thread waits for, or null: the one taker registers it, the next message completes it. */
    private final AtomicReference<CompletableFuture<Void>> waiting = new AtomicReference<>();
    /** The ticket of the agent's park until the next message, or 0: its slice registers it, the next message ends it. */
    private final AtomicLong parked = new AtomicLong();
    /** The agent parked with {@link #parked}: written before it, read after it. */
    private AgentContext agent;

    /** A message came (any thread): queued, and the agent parked for it, or the thread waiting for it, let go. */
    void add(ObjectNode message) {
        messages.add(message);
        long ticket = parked.getAndSet(0);
        if (ticket != 0) {
            DeployedPrograms.arrivedElsewhere(agent, ticket);
        }
        if (waiting.get() != null) {
            CompletableFuture<Void> arrival = waiting.getAndSet(null);
            if (arrival != null) {
                arrival.complete(null);
            }
        }
    }

    /** The next message, or null if none has come. */
    ObjectNode poll() {
        return messages.poll();
    }

    /**
     * Parks {@code ctx}, the agent's context, until the next message, at once let go if one is here
     * (registered before the queue is read again, and {@link #add} queues before it reads the
     * registration, so one of them sees the other): false, and nothing done, where the runtime cannot
     * park it so ({@link DeployedPrograms#awaitElsewhere}). Called by the agent's slice.
     */
    boolean awaitElsewhere(AgentContext ctx) {
        long ticket = DeployedPrograms.awaitElsewhere(ctx);
        if (ticket == 0) {
            return false;
        }
        agent = ctx;
        parked.set(ticket);
        if (!messages.isEmpty() && parked.compareAndSet(ticket, 0)) {
            DeployedPrograms.arrivedElsewhere(ctx, ticket);
        }
        return true;
    }

    /**
     * Completes once a message is here, at once if one is: registered before the queue is read again,
     * and {@link #add} queues before it reads the registration, so one of them sees the other.
     */
    CompletableFuture<Void> arrival() {
        CompletableFuture<Void> arrival = new CompletableFuture<>();
        waiting.set(arrival);
        if (!messages.isEmpty() && waiting.compareAndSet(arrival, null)) {
            arrival.complete(null);
        }
        return arrival;
    }
}
