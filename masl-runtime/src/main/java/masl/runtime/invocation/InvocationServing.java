package masl.runtime.invocation;

import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.scheduling.ScheduledAgent;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * The external invocations queued at one agent, the callee (MASL §9), and how they are served.
 *
 * <p>An invocation is a {@link PendingInvocation} in this queue, added from any thread. Whoever
 * serves it (the callee at a step boundary, or a serving slice on its behalf while it is blocked,
 * see {@link masl.runtime.scheduling.RunState}) decides at that moment, from the callee's current
 * permeability state and the requester's relation to it ({@link Permeability#permits}), whether
 * it runs or is denied. While the callee is in {@code wait(state)} it is <em>attentive</em>
 * ({@link #attend}): serving then runs only the first pending invocation that state allows, which
 * ends the wait by the park's ticket (a timer races for the same ticket, {@link #stopAttending});
 * the others stay queued for the next boundary.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class InvocationServing {

    private final Queue<PendingInvocation> invocations = new ConcurrentLinkedQueue<>();
    /** The ticket of the park of a pending {@code wait(state)}, 0 if none: who zeroes it ends the wait. */
    private final AtomicLong attentiveTicket = new AtomicLong();
    /** The state of the pending {@code wait(state)}; read only while {@link #attentiveTicket} is set. */
    private volatile PermeabilityState attentiveState;
    private final ScheduledAgent callee;
    private final Permeability permeability;
    private final Trace trace;
    private final LongSupplier clock;

    public InvocationServing(ScheduledAgent callee, Permeability permeability, Trace trace, LongSupplier clock) {
        this.callee = callee;
        this.permeability = permeability;
        this.trace = trace;
        this.clock = clock;
    }

    /** Queues an invocation; from any thread. */
    public void add(PendingInvocation invocation) {
        invocations.add(invocation);
    }

    public boolean nothingQueued() {
        return invocations.isEmpty();
    }

    /** In {@code wait(state)}: only an invocation that state allows is served, and it ends the wait. */
    public boolean isAttentive() {
        return attentiveTicket.get() != 0;
    }

    /** {@code wait(state)} parked with {@code ticket}: attentive to {@code state} until the wait ends. */
    public void attend(PermeabilityState state, long ticket) {
        attentiveState = state;
        attentiveTicket.set(ticket);
    }

    /** The wait's timeout: true if it came first and ends the wait parked with {@code ticket}. */
    public boolean stopAttending(long ticket) {
        return attentiveTicket.compareAndSet(ticket, 0);
    }

    /**
     * Step 2 of a boundary, or a serving slice (§5): every pending invocation in order, each run or
     * denied by the current state; while attentive (in {@code wait(state)}), only the first one that
     * state allows, which then ends the wait.
     */
    public void serveAll() {
        long attentive = attentiveTicket.get();
        if (attentive != 0) {
            serveAttentively(attentive);
            return;
        }
        PendingInvocation invocation;
        while ((invocation = invocations.poll()) != null) {
            PermeabilityState state = permeability.current();
            if (permeability.permits(state, invocation)) {
                serve(invocation);
            } else {
                trace.record(new TraceEvent.InvocationDenied(clock.getAsLong(), callee.id(), invocation.requesterId(),
                        invocation.primitive(), permeability.currentName(), callee.source()));
                invocation.deny();
            }
        }
    }

    private void serveAttentively(long ticket) {
        PendingInvocation allowed = firstAllowedBy(attentiveState);
        // The timeout of the wait may have won: then the invocation waits for the next boundary.
        if (allowed == null || !attentiveTicket.compareAndSet(ticket, 0)) {
            return;
        }
        invocations.remove(allowed);
        serve(allowed);
        callee.unpark(ticket);
    }

    /** {@code wait(state)} finds an invocation {@code state} allows already queued: serves it, true; false if none. */
    public boolean serveFirstAllowedBy(PermeabilityState state) {
        PendingInvocation allowed = firstAllowedBy(state);
        if (allowed == null) {
            return false;
        }
        invocations.remove(allowed);
        serve(allowed);
        return true;
    }

    private void serve(PendingInvocation invocation) {
        trace.record(new TraceEvent.InvocationServed(clock.getAsLong(), callee.id(), invocation.requesterId(),
                invocation.primitive(), callee.source()));
        invocation.run();
    }

    /** Whether a serving slice has something to run: any pending invocation, or while attentive one it allows. */
    public boolean hasServable() {
        if (invocations.isEmpty()) {
            return false;
        }
        return attentiveTicket.get() == 0 || firstAllowedBy(attentiveState) != null;
    }

    private PendingInvocation firstAllowedBy(PermeabilityState state) {
        for (PendingInvocation invocation : invocations) {
            if (permeability.permits(state, invocation)) {
                return invocation;
            }
        }
        return null;
    }
}
