package masl.runtime.scheduling;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import masl.runtime.Agent;

/**
 * A mission-wide counter of changes an agent's busy-wait loop can observe (MASL §5): shared
 * variable writes, membership and lock policy changes, queued invocations. An agent whose
 * busy-wait iteration saw nothing new parks here until the counter moves on.
 *
 * <p><b>No lost wake-up:</b> a waiter registers in the current queue, then re-reads the counter
 * and checks that its queue is still the current one; {@link #advance} increments the counter
 * before it swaps the queue out and drains it. So an advance either comes after the waiter's
 * checks and drains the queue it registered in, or the waiter sees it and wakes itself. <b>No
 * livelock:</b> an advance wakes only the waiters registered in the queue it swapped out; a woken
 * agent that finds nothing new parks again in the fresh queue, for the next advance, instead of
 * being woken again and again by the same one.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class ChangeEpoch {

    private record Waiter(Agent agent, long ticket) { }

    private final AtomicLong epoch = new AtomicLong();
    private final AtomicReference<ConcurrentLinkedQueue<Waiter>> waiters =
            new AtomicReference<>(new ConcurrentLinkedQueue<>());

    public long current() {
        return epoch.get();
    }

    /** Records a change and wakes every agent waiting for one. */
    public void advance() {
        epoch.incrementAndGet();
        if (waiters.get().isEmpty()) {
            // A waiter registering now re-reads the epoch after registering, and wakes itself.
            return;
        }
        ConcurrentLinkedQueue<Waiter> woken = waiters.getAndSet(new ConcurrentLinkedQueue<>());
        Waiter waiter;
        while ((waiter = woken.poll()) != null) {
            waiter.agent().unpark(waiter.ticket());
        }
    }

    /**
     * Parks {@code agent} (which is running and calls this itself) until the epoch differs from
     * {@code seen}; if it already does, the agent is made runnable again at once. Returns the
     * park's ticket, with which others may end it earlier.
     */
    public long parkUntilChanged(Agent agent, long seen) {
        long ticket = agent.prepareToPark();
        ConcurrentLinkedQueue<Waiter> queue = waiters.get();
        queue.add(new Waiter(agent, ticket));
        // An advance that had swapped this queue out already would never drain it again.
        if (waiters.get() != queue || epoch.get() != seen) {
            agent.unpark(ticket);
        }
        return ticket;
    }
}
