package masl.jade.deployment;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicReference;

/**
 * The messages of a deployed agent's step for its stand-in (requests, the step's end), in the order
 * they came, which the agent's slices take one at a time. A slice that finds none waits for the next
 * without a thread: {@link #arrival} completes once one is here, on the thread that brings it.
 *
 * <p><b>Memory consistency effects.</b> Actions of a thread before it {@linkplain #add adds} a
 * message happen-before the actions of the slice that {@linkplain #poll takes} it, and of whoever
 * the arrival it completes runs.
 */
final class StepMessages {

    private final ConcurrentLinkedQueue<ObjectNode> messages = new ConcurrentLinkedQueue<>();
    /** The arrival a slice waits for, or null: the one taker registers it, the next message completes it. */
    private final AtomicReference<CompletableFuture<Void>> waiting = new AtomicReference<>();

    /** A message came (any thread): queued, and the waiting arrival, if any, completed. */
    void add(ObjectNode message) {
        messages.add(message);
        CompletableFuture<Void> arrival = waiting.getAndSet(null);
        if (arrival != null) {
            arrival.complete(null);
        }
    }

    /** The next message, or null if none has come. */
    ObjectNode poll() {
        return messages.poll();
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
