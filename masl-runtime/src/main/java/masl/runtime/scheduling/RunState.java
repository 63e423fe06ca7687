package masl.runtime.scheduling;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.function.BooleanSupplier;

/**
 * The scheduling state of one agent and the tickets of its parks: who may run it, and which
 * wake-up ends which wait. Safe from any thread; the ticket counter is confined to the agent's
 * slices. The agent's bottom layer ({@link ScheduledAgent} extends it), not an object it points
 * to: every agent-step in lock-step reads and updates the word twice, and a word in an object of
 * its own was one more cache line and one more dependent load per agent-step (at 100,000 agents,
 * one more miss to memory).
 *
 * <p><b>States.</b> {@code SCHEDULED → RUNNING} when a slice starts ({@link #startSlice}). A
 * runtime call that must wait issues a park <em>ticket</em> ({@link #issueTicket}) and the program
 * returns; the slice then ends {@code RUNNING → PARKED} ({@link #park}). Whoever ends the wait
 * {@linkplain #endPark ends its park} the agent with that ticket: the first to come with the pending
 * ticket wins, a stale or repeated one does nothing. The winner finds the agent {@code PARKED},
 * turns it {@code SCHEDULED} and hands it to the scheduler; a wake-up that comes while the slice is
 * still running turns {@code RUNNING → RUNNING_WOKEN}, and the slice reschedules the agent when it
 * returns ({@link #park} fails). A program that has finished leaves the agent {@code DONE}. An agent
 * whose step runs in another JVM (a deployed agent's) ends its slice {@code RUNNING → AWAY}
 * ({@link #parkAway}) while it waits for that step's next message: woken as from {@code PARKED}, but
 * its program is not blocked, so nobody serves its invocations on its behalf, and the deadlock
 * watchdog does not count it idle.
 *
 * <p><b>Serving while blocked</b> (MASL §5). An invocation queued for a {@code PARKED} or
 * {@code DONE} agent turns it {@code SERVING} ({@link #claimServing}), and whoever did runs the
 * pending invocations on its behalf, without running its program, then returns it to where it was;
 * its park's ticket stays pending meanwhile. A wake-up that comes meanwhile turns
 * {@code SERVING → SERVING_WOKEN}, and the serving slice then schedules the program. So an agent is
 * never run by two threads at once, its program and the invocations it serves never overlap, and no
 * wake-up or invocation is lost.
 *
 * <p><b>One word.</b> The state and the pending ticket are one {@code long} ({@code ticket << 3 |
 * state}), so that an unpark checks the ticket and leaves {@code PARKED} in one compare-and-set,
 * and issuing a ticket is a release store: while its slice runs with no ticket pending, nobody but
 * the agent's own slice can change the word (an unpark needs a pending ticket, a serving claim a
 * parked or finished agent). A lock-step agent-step is then two atomic updates of the agent's
 * word, its park and its unpark, besides the start of its slice.
 *
 * <p><b>Memory consistency effects.</b> Actions of a slice before it issues a ticket happen-before
 * the actions of whoever reads that ticket pending and {@linkplain #endPark ends its park} with it (a
 * release store, read by the unpark's volatile read and compare-and-set). Actions of a thread before
 * a successful {@code endPark} or {@code claimServing} happen-before the actions of the slice that the
 * scheduler then runs for the agent. Actions of a slice before {@link #park} happen-before the
 * actions of a waker whose {@code endPark} returns true. These races are checked by the jcstress
 * tests {@code RunStateParkOrWakeUp}, {@code RunStateTwoWakeUps} and {@code RunStateServeOrWakeUp}.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public abstract class RunState {

    private static final int SCHEDULED = 0;
    private static final int RUNNING = 1;
    private static final int RUNNING_WOKEN = 2;
    private static final int PARKED = 3;
    private static final int SERVING = 4;
    private static final int SERVING_WOKEN = 5;
    private static final int DONE = 6;
    /** Parked while its step goes on elsewhere: woken as from {@code PARKED}, but neither blocked nor idle. */
    private static final int AWAY = 7;

    private static final int STATE_BITS = 3;
    private static final long STATE_MASK = (1L << STATE_BITS) - 1;

    // Updated through a VarHandle rather than an AtomicLong of its own: one object is one cache line
    // to fetch where two were. Its arguments have the field's exact type (long): a call
    // whose types differ (an int literal) takes VarHandle's adapting path, a method-handle chain the
    // JIT does not reduce to one CAS.
    private static final VarHandle WORD;

    static {
        try {
            WORD = MethodHandles.lookup().findVarHandle(RunState.class, "word", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    /** {@code pendingTicket << STATE_BITS | state}; the pending ticket is 0 if none. */
    private volatile long word = SCHEDULED;
    /** Confined to the agent's slices (successive slices are ordered). */
    private long lastTicket;

    /** Describes the agent, for the messages of broken rules. */
    public abstract String describe();

    /** Counts a parked agent made runnable, for the deadlock watchdog. */
    protected abstract void countWakeUp();

    private static int stateOf(long word) {
        return (int) (word & STATE_MASK);
    }

    private static long ticketOf(long word) {
        return word >>> STATE_BITS;
    }

    private static long withState(long word, int state) {
        return (word & ~STATE_MASK) | state;
    }

    /** {@code SERVING} or {@code SERVING_WOKEN}: the slice about to run serves invocations only. */
    protected final boolean isServing() {
        int current = stateOf(word);
        return current == SERVING || current == SERVING_WOKEN;
    }

    /** {@code SCHEDULED → RUNNING}; false, and no change, from any other state (a runtime bug). */
    protected final boolean startSlice() {
        return WORD.compareAndSet(this, (long) SCHEDULED, (long) RUNNING);
    }

    /** The state's name, for the message of a broken rule. */
    protected final String describeState() {
        return String.valueOf(stateOf(word));
    }

    /**
     * Ends the current slice, running ({@code serving} false) or serving, {@code → PARKED}: false if
     * a wake-up came meanwhile, and the caller must then {@link #reschedule}. Only a wake-up changes
     * the word of a running or serving slice, so a failed update is one.
     */
    protected final boolean park(boolean serving) {
        long current = word;
        return stateOf(current) == (serving ? SERVING : RUNNING)
                && WORD.compareAndSet(this, current, withState(current, PARKED));
    }

    /**
     * Ends the current (running) slice {@code → AWAY}: false if a wake-up came meanwhile, and the
     * caller must then {@link #reschedule}, as after {@link #park}.
     */
    protected final boolean parkAway() {
        long current = word;
        return stateOf(current) == RUNNING && WORD.compareAndSet(this, current, withState(current, AWAY));
    }

    /** Back to {@code SCHEDULED}, after a wake-up ended the park: the caller hands the agent to the scheduler. */
    protected final void reschedule() {
        word = SCHEDULED;
    }

    /** The agent's program is over. */
    protected final void done() {
        word = DONE;
    }

    public final boolean isDone() {
        return stateOf(word) == DONE;
    }

    protected final boolean isParked() {
        return stateOf(word) == PARKED;
    }

    /**
     * Idle for the deadlock watchdog: done with {@code nothingQueued}, or parked with nothing queued
     * or {@code attentive} (in {@code wait(state)}). The caller reads its queue before this call, so
     * the one read of the state here says whether the agent was idle at that instant.
     */
    protected final boolean isIdle(boolean nothingQueued, BooleanSupplier attentive) {
        int current = stateOf(word);
        if (current == DONE) {
            return nothingQueued;
        }
        return current == PARKED && (nothingQueued || attentive.getAsBoolean());
    }

    /**
     * Turns a blocked or finished agent {@code SERVING} while {@code servable} says invocations wait
     * for it: true if this caller did and must now serve them (or have them served). Leaving
     * {@code PARKED} is counted as a schedule, as a wake-up is; {@code SERVING} is not idle. The
     * pending ticket stays: the agent still waits for its park to end.
     */
    protected final boolean claimServing(BooleanSupplier servable) {
        while (servable.getAsBoolean()) {
            long current = word;
            int state = stateOf(current);
            if (state == PARKED) {
                countWakeUp();
            } else if (state != DONE) {
                return false;
            }
            if (WORD.compareAndSet(this, current, withState(current, SERVING))) {
                return true;
            }
        }
        return false;
    }

    /**
     * Issues the ticket of a park, which becomes the pending one. Called by the agent's running
     * slice with no ticket pending, when nobody else can change the word: a release store is enough,
     * and whoever learns the ticket (through the barrier, the future or the queue it is handed to)
     * sees it pending.
     */
    protected final long issueTicket() {
        long ticket = ++lastTicket;
        long current = (long) WORD.getOpaque(this);
        WORD.setRelease(this, ticket << STATE_BITS | stateOf(current));
        return ticket;
    }

    /** Takes back the pending park {@code ticket}, which nobody has ended: false if someone has. */
    protected final boolean takeBack(long ticket) {
        long current = word;
        return ticketOf(current) == ticket && WORD.compareAndSet(this, current, current & STATE_MASK);
    }

    /** The ticket of the pending park, or 0 if the agent has none (it is running, not waiting). */
    public final long pendingTicket() {
        return ticketOf(word);
    }

    /**
     * Ends the park {@code ticket} straight into a slice, {@code PARKED → RUNNING}, for a thread that
     * runs the slice itself at once and holds a pending wake-up for the agent (a pass over the
     * agents a barrier trip let go): one update where an {@link #endPark} and the slice's
     * {@link #startSlice} take two. False, and no change, unless the agent is parked with that ticket
     * (serving meanwhile, or that park has ended): the caller then ends the park as {@code endPark}
     * does. Counted for the deadlock watchdog as an unpark is, by the caller, before.
     */
    protected final boolean resumeParked(long ticket) {
        long parked = ticket << STATE_BITS | PARKED;
        return word == parked && WORD.compareAndSet(this, parked, (long) RUNNING);
    }

    /**
     * Ends the park that issued {@code ticket}, unless it has ended already: true if the agent went
     * {@code PARKED → SCHEDULED} (or {@code AWAY → SCHEDULED}) and the caller must hand it to the scheduler; false if that park
     * had ended (a stale or repeated ticket), or if the agent's slice, running or serving, notes the
     * wake-up and reschedules it. The caller counts the wake-up for the deadlock watchdog before,
     * or holds a pending one.
     */
    public final boolean endPark(long ticket) {
        if (ticket == 0) {
            return false;
        }
        while (true) {
            long current = word;
            if (ticketOf(current) != ticket) {
                return false;
            }
            int state = stateOf(current);
            int next = switch (state) {
                case PARKED, AWAY -> SCHEDULED;
                case RUNNING -> RUNNING_WOKEN;
                case SERVING -> SERVING_WOKEN;
                case DONE -> DONE;
                default -> throw new IllegalStateException(describe() + " woken twice");
            };
            if (WORD.compareAndSet(this, current, (long) next)) {
                return state == PARKED || state == AWAY;
            }
        }
    }
}
