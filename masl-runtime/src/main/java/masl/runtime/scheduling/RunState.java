package masl.runtime.scheduling;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

/**
 * The scheduling state of one agent and the tickets of its parks: who may run it, and which
 * wake-up ends which wait. Safe from any thread; the ticket counter is confined to the agent's
 * slices.
 *
 * <p><b>States.</b> {@code SCHEDULED → RUNNING} when a slice starts ({@link #startSlice}). A
 * runtime call that must wait issues a park <em>ticket</em> ({@link #issueTicket}) and the program
 * returns; the slice then ends {@code RUNNING → PARKED} ({@link #park}). Whoever ends the wait
 * claims that ticket ({@link #endPark}): the first claim of the current ticket wins, a stale or
 * repeated one fails. Then {@link #leavePark}: {@code PARKED → SCHEDULED}, and the claimant hands
 * the agent to the scheduler; a wake-up that comes while the slice is still running turns
 * {@code RUNNING → RUNNING_WOKEN}, and the slice reschedules the agent when it returns
 * ({@link #park} fails). A program that has finished leaves the agent {@code DONE}.
 *
 * <p><b>Serving while blocked</b> (MASL §5). An invocation queued for a {@code PARKED} or
 * {@code DONE} agent turns it {@code SERVING} ({@link #claimServing}), and whoever did runs the
 * pending invocations on its behalf, without running its program, then returns it to where it was.
 * A wake-up that comes meanwhile turns {@code SERVING → SERVING_WOKEN}, and the serving slice then
 * schedules the program. So an agent is never run by two threads at once, its program and the
 * invocations it serves never overlap, and no wake-up or invocation is lost.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class RunState {

    private static final int SCHEDULED = 0;
    private static final int RUNNING = 1;
    private static final int RUNNING_WOKEN = 2;
    private static final int PARKED = 3;
    private static final int SERVING = 4;
    private static final int SERVING_WOKEN = 5;
    private static final int DONE = 6;

    private final AtomicInteger state = new AtomicInteger(SCHEDULED);
    /** The ticket of the pending park, 0 if none. */
    private final AtomicLong wakeTicket = new AtomicLong();
    /** Confined to the agent's slices (successive slices are ordered). */
    private long lastTicket;
    private final Supplier<String> owner;
    private final Runnable countSchedule;

    /**
     * @param owner describes the agent, for the messages of broken rules
     * @param countSchedule counts a parked agent made runnable, for the deadlock watchdog
     */
    public RunState(Supplier<String> owner, Runnable countSchedule) {
        this.owner = owner;
        this.countSchedule = countSchedule;
    }

    /** {@code SERVING} or {@code SERVING_WOKEN}: the slice about to run serves invocations only. */
    public boolean isServing() {
        int current = state.get();
        return current == SERVING || current == SERVING_WOKEN;
    }

    /** {@code SCHEDULED → RUNNING}; false, and no change, from any other state (a runtime bug). */
    public boolean startSlice() {
        return state.compareAndSet(SCHEDULED, RUNNING);
    }

    /** The state's name, for the message of a broken rule. */
    public String describeState() {
        return String.valueOf(state.get());
    }

    /**
     * Ends the current slice, running ({@code serving} false) or serving, {@code → PARKED}: false if
     * a wake-up came meanwhile, and the caller must then {@link #reschedule}.
     */
    public boolean park(boolean serving) {
        return state.compareAndSet(serving ? SERVING : RUNNING, PARKED);
    }

    /** Back to {@code SCHEDULED}: the caller hands the agent to the scheduler. */
    public void reschedule() {
        state.set(SCHEDULED);
    }

    /** The agent's program is over. */
    public void done() {
        state.set(DONE);
    }

    public boolean isDone() {
        return state.get() == DONE;
    }

    public boolean isParked() {
        return state.get() == PARKED;
    }

    /**
     * Idle for the deadlock watchdog: done with {@code nothingQueued}, or parked with nothing queued
     * or {@code attentive} (in {@code wait(state)}). The caller reads its queue before this call, so
     * the one read of the state here says whether the agent was idle at that instant.
     */
    public boolean isIdle(boolean nothingQueued, BooleanSupplier attentive) {
        int current = state.get();
        if (current == DONE) {
            return nothingQueued;
        }
        return current == PARKED && (nothingQueued || attentive.getAsBoolean());
    }

    /**
     * Turns a blocked or finished agent {@code SERVING} while {@code servable} says invocations wait
     * for it: true if this caller did and must now serve them (or have them served). Leaving
     * {@code PARKED} is counted as a schedule, as a wake-up is; {@code SERVING} is not idle.
     */
    public boolean claimServing(BooleanSupplier servable) {
        while (servable.getAsBoolean()) {
            int current = state.get();
            if (current == PARKED) {
                countSchedule.run();
            } else if (current != DONE) {
                return false;
            }
            if (state.compareAndSet(current, SERVING)) {
                return true;
            }
        }
        return false;
    }

    /** Issues the ticket of a park, which becomes the pending one. */
    public long issueTicket() {
        long ticket = ++lastTicket;
        wakeTicket.set(ticket);
        return ticket;
    }

    /** Takes back the pending park {@code ticket}, which nobody has ended: false if someone has. */
    public boolean takeBack(long ticket) {
        return wakeTicket.compareAndSet(ticket, 0);
    }

    /** The ticket of the pending park, or 0 if the agent has none (it is running, not waiting). */
    public long pendingTicket() {
        return wakeTicket.get();
    }

    /**
     * Claims the end of the park that issued {@code ticket}, the first half of a wake-up: false if
     * that park already ended. The claimant must then call {@link #leavePark()}.
     */
    public boolean endPark(long ticket) {
        return ticket != 0 && wakeTicket.compareAndSet(ticket, 0);
    }

    /**
     * The second half of a wake-up whose {@link #endPark} succeeded, after the watchdog's count:
     * true if the agent went {@code PARKED → SCHEDULED} and the caller must hand it to the
     * scheduler; false if its slice (running or serving) notes the wake-up and reschedules it.
     */
    public boolean leavePark() {
        while (true) {
            int current = state.get();
            if (current == PARKED && state.compareAndSet(PARKED, SCHEDULED)) {
                return true;
            }
            if (current == RUNNING && state.compareAndSet(RUNNING, RUNNING_WOKEN)) {
                return false;
            }
            if (current == SERVING && state.compareAndSet(SERVING, SERVING_WOKEN)) {
                return false;
            }
            if (current == DONE) {
                return false;
            }
            if (current == SCHEDULED || current == RUNNING_WOKEN || current == SERVING_WOKEN) {
                throw new IllegalStateException(owner.get() + " woken twice");
            }
        }
    }
}
