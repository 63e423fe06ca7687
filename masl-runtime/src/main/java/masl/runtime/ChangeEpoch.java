package masl.runtime;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;

/**
 * A mission-wide counter of changes an agent's busy-wait loop can observe (MASL §5): shared
 * variable writes, membership and lock policy changes, queued events and invocations. An agent
 * whose busy-wait iteration saw nothing new parks here until the counter moves on.
 *
 * <p>No lost wake-up: a waiter registers before it re-reads the counter, and {@link #advance}
 * increments the counter before it wakes the registered waiters.
 */
final class ChangeEpoch {

    private record Waiter(Agent agent, long ticket) { }

    private final AtomicLong epoch = new AtomicLong();
    private final ConcurrentLinkedQueue<Waiter> waiters = new ConcurrentLinkedQueue<>();

    long current() {
        return epoch.get();
    }

    /** Records a change and wakes every agent waiting for one. */
    void advance() {
        epoch.incrementAndGet();
        Waiter waiter;
        while ((waiter = waiters.poll()) != null) {
            waiter.agent().unpark(waiter.ticket());
        }
    }

    /**
     * Parks {@code agent} (which is running and calls this itself) until the epoch differs from
     * {@code seen}; if it already does, the agent is made runnable again at once.
     */
    void parkUntilChanged(Agent agent, long seen) {
        long ticket = agent.prepareToPark();
        waiters.add(new Waiter(agent, ticket));
        if (epoch.get() != seen) {
            agent.unpark(ticket);
        }
    }
}
