package masl.runtime.scheduling;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
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

    // Fields updated through VarHandles rather than atomic objects of their own: a step reads and
    // updates both, and one object is one cache line to fetch where three were (issue 26). Their
    // arguments have the field's exact type (0L for the ticket, not 0): a call whose types differ
    // takes VarHandle's adapting path, a method-handle chain the JIT does not reduce to one CAS.
    private static final VarHandle STATE;
    private static final VarHandle WAKE_TICKET;

    static {
        try {
            MethodHandles.Lookup lookup = MethodHandles.lookup();
            STATE = lookup.findVarHandle(RunState.class, "state", int.class);
            WAKE_TICKET = lookup.findVarHandle(RunState.class, "wakeTicket", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    private volatile int state = SCHEDULED;
    /** The ticket of the pending park, 0 if none. */
    private volatile long wakeTicket;
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
        int current = state;
        return current == SERVING || current == SERVING_WOKEN;
    }

    /** {@code SCHEDULED → RUNNING}; false, and no change, from any other state (a runtime bug). */
    public boolean startSlice() {
        return STATE.compareAndSet(this, SCHEDULED, RUNNING);
    }

    /** The state's name, for the message of a broken rule. */
    public String describeState() {
        return String.valueOf(state);
    }

    /**
     * Ends the current slice, running ({@code serving} false) or serving, {@code → PARKED}: false if
     * a wake-up came meanwhile, and the caller must then {@link #reschedule}.
     */
    public boolean park(boolean serving) {
        return STATE.compareAndSet(this, serving ? SERVING : RUNNING, PARKED);
    }

    /** Back to {@code SCHEDULED}: the caller hands the agent to the scheduler. */
    public void reschedule() {
        state = SCHEDULED;
    }

    /** The agent's program is over. */
    public void done() {
        state = DONE;
    }

    public boolean isDone() {
        return state == DONE;
    }

    public boolean isParked() {
        return state == PARKED;
    }

    /**
     * Idle for the deadlock watchdog: done with {@code nothingQueued}, or parked with nothing queued
     * or {@code attentive} (in {@code wait(state)}). The caller reads its queue before this call, so
     * the one read of the state here says whether the agent was idle at that instant.
     */
    public boolean isIdle(boolean nothingQueued, BooleanSupplier attentive) {
        int current = state;
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
            int current = state;
            if (current == PARKED) {
                countSchedule.run();
            } else if (current != DONE) {
                return false;
            }
            if (STATE.compareAndSet(this, current, SERVING)) {
                return true;
            }
        }
        return false;
    }

    /** Issues the ticket of a park, which becomes the pending one. */
    public long issueTicket() {
        long ticket = ++lastTicket;
        wakeTicket = ticket;
        return ticket;
    }

    /** Takes back the pending park {@code ticket}, which nobody has ended: false if someone has. */
    public boolean takeBack(long ticket) {
        return WAKE_TICKET.compareAndSet(this, ticket, 0L);
    }

    /** The ticket of the pending park, or 0 if the agent has none (it is running, not waiting). */
    public long pendingTicket() {
        return wakeTicket;
    }

    /**
     * Claims the end of the park that issued {@code ticket}, the first half of a wake-up: false if
     * that park already ended. The claimant must then call {@link #leavePark()}.
     */
    public boolean endPark(long ticket) {
        return ticket != 0 && WAKE_TICKET.compareAndSet(this, ticket, 0L);
    }

    /**
     * The second half of a wake-up whose {@link #endPark} succeeded, after the watchdog's count:
     * true if the agent went {@code PARKED → SCHEDULED} and the caller must hand it to the
     * scheduler; false if its slice (running or serving) notes the wake-up and reschedules it.
     */
    public boolean leavePark() {
        while (true) {
            int current = state;
            if (current == PARKED && STATE.compareAndSet(this, PARKED, SCHEDULED)) {
                return true;
            }
            if (current == RUNNING && STATE.compareAndSet(this, RUNNING, RUNNING_WOKEN)) {
                return false;
            }
            if (current == SERVING && STATE.compareAndSet(this, SERVING, SERVING_WOKEN)) {
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
