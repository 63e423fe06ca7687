package masl.runtime.event;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

/**
 * The occurrences an agent has perceived and not yet taken (MASL §8): many emitters, one taker,
 * lock-free. An emitter pushes with one compare-and-set, so it never waits for the receiver;
 * {@link #takeAll()} detaches everything perceived so far in one atomic swap, which is exactly the
 * set §8 processes at a step boundary (what comes later waits for the next one).
 *
 * <p><b>Order.</b> Occurrences are taken in the order their pushes took effect, so the occurrences
 * of one emitter keep the order in which it emitted them.
 */
final class EventQueue {

    private record Node(EventOccurrence occurrence, Node below) { }

    private final AtomicReference<Node> top = new AtomicReference<>();

    /** Adds an occurrence; safe from any thread, never blocks. */
    void offer(EventOccurrence occurrence) {
        Node current;
        do {
            current = top.get();
        } while (!top.compareAndSet(current, new Node(occurrence, current)));
    }

    /** Removes and returns every occurrence offered so far, oldest first. */
    List<EventOccurrence> takeAll() {
        Node node = top.getAndSet(null);
        List<EventOccurrence> taken = new ArrayList<>();
        for (; node != null; node = node.below()) {
            taken.add(node.occurrence());
        }
        Collections.reverse(taken);
        return taken;
    }

    boolean isEmpty() {
        return top.get() == null;
    }
}
