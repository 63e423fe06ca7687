package masl.runtime.entry;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import masl.runtime.Agent;

/**
 * The synchronisation barrier of one barrier domain (MASL §6.3, §6.4): an outermost synchronous
 * block and all its synchronous descendants reached through synchronous parents. Unlike a
 * {@link java.util.concurrent.Phaser} it never blocks a thread: an arriving agent is parked as data
 * and a trip makes the parked agents runnable. Like a {@code Phaser}, an arrival that does not
 * complete the barrier takes no lock.
 *
 * <p><b>Participants.</b> The agents with a membership of a block of the domain that are held by
 * no entry or exit barrier (anywhere in their chain). Membership is dynamic: the
 * {@link EntryCoordinator} adds and removes participants, under its lock, as agents join, are
 * held, are released, leave and die. A domain without participants never trips.
 *
 * <p><b>State.</b> One atomic long packs the <em>phase</em> (the number of trips so far, modulo
 * 2<sup>22</sup>), the number of <em>participants</em> and the number of them still
 * <em>unarrived</em> in this phase (21 bits each: at most 2,097,151 participants). Agents that
 * arrived one by one in the phase wait on a lock-free stack linked through the agents themselves
 * ({@link Agent#nextArrival}), so such an arrival allocates nothing; arrivals published together
 * wait as chunks ({@link ArrivalChunk}) on a second stack.
 *
 * <p><b>Transitions.</b>
 * <ul>
 * <li><b>Arrive</b> ({@link #arrive}, no lock, by the arriving participant, which has issued the
 *     ticket of its park; or {@link #arriveAll}, for a chunk of parked participants at once, by the
 *     thread that ran their slices): push the agent or the chunk onto its stack, <em>then</em>
 *     decrement unarrived. Every agent counted as arrived is therefore on a stack. The arrival that brings
 *     unarrived to zero has <em>completed</em> the phase; every other one is simply parked.</li>
 * <li><b>Add or remove a participant</b> ({@link #addParticipant}, {@link #removeParticipant},
 *     under the coordinator's lock): participants and unarrived change together, by one, since a
 *     joining or leaving participant has not arrived. The one exception is an agent whose program
 *     died after it arrived: only participants drop, its arrival stays counted.</li>
 * <li><b>Spin</b> ({@link #wakeOnArrival}, no lock): a participant in an idle iteration of a busy-wait
 *     that would change nothing (MASL §5) parks without arriving, on a third stack, while nobody has
 *     arrived in the phase; every arrival then takes that stack and wakes them, so they arrive late
 *     in the phase, never miss it, and a phase never trips without them.</li>
 * <li><b>Trip</b> ({@link #trip}, under the coordinator's lock, only when unarrived is zero and
 *     participants are not): advance the phase, set unarrived to participants, take both stacks
 *     and let the agents go in arrival order, then the chunks, whole, in publication order.</li>
 * </ul>
 *
 * <p><b>Who trips, exactly once.</b> Trips happen only under the lock, and a trip moves the phase
 * on, so the lock orders every trip and every membership change and the trace lists them in that
 * order. A completing arrival takes the lock and trips if its phase is still the current one and
 * still complete ({@link #completes}). Two things may come between its decrement and its taking
 * the lock, each as one atomic step under the lock:
 * <ul>
 * <li>a participant joins (or is released into the domain): unarrived is no longer zero, so the
 *     join counts as having come before the completing arrival, whose agent stays parked on the
 *     stack until the joiner arrives too; a barrier never trips with a participant missing;</li>
 * <li>a change completes the phase itself (the joiner leaves again, or is held; an arrived agent
 *     dies) and trips it, waking every stacked agent, the completing one included, which then finds
 *     its phase gone and returns parked and already woken.</li>
 * </ul>
 * A membership change that leaves unarrived at zero (a non-arrived participant leaving, held or
 * dying while all the others have arrived) trips in its own atomic step, after everything else it
 * caused ({@link EntryCoordinator}'s settle). The trip's {@code BarrierTripped} record therefore
 * counts exactly the participants at the trip, all of which have arrived, and no arrival between
 * two trips is lost: an arrival for the next phase is pushed only once its agent was let go by the
 * trip, or, for a joiner, after its join, which comes after the previous trip under the lock.
 *
 * <p><b>Memory consistency effects.</b> Actions of an agent's slice before its arrival happen-before
 * the actions of the thread that trips the phase (the arrival's push and count are atomic updates
 * that the completing arrival or the tripping change reads), and the trip's hand-over of the agents
 * to the scheduler makes them happen-before each agent's next slice: what every participant wrote in
 * a step is visible to every participant in the next. Checked by the jcstress tests
 * {@code BarrierLastArrival} (concurrent arrivals) and {@code BarrierArrivalOrJoin} (an arrival
 * against a join).
 *
 * <p><b>Trace.</b> An arrival writes no trace record: it changes no membership, and a record of
 * it, written without the lock, could only be ordered against the others by a clock. The trip is
 * the record of a completed phase, written under the lock among the membership changes.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class SynchronisationBarrier {

    private static final int COUNT_BITS = 21;
    private static final long COUNT_MASK = (1L << COUNT_BITS) - 1;
    private static final int PARTICIPANTS_SHIFT = COUNT_BITS;
    private static final int PHASE_SHIFT = 2 * COUNT_BITS;
    private static final long PHASE_MASK = (1L << (Long.SIZE - PHASE_SHIFT)) - 1;
    private static final long ONE_UNARRIVED = 1;
    private static final long ONE_PARTICIPANT = 1L << PARTICIPANTS_SHIFT;

    /** The outermost block of the domain, naming it in traces and reports. */
    final Entry domain;
    private final AtomicLong state = new AtomicLong();
    /** The agents that arrived one by one in the current phase, last arrival first, linked by {@link Agent#nextArrival}. */
    private final AtomicReference<Agent> arrivals = new AtomicReference<>();
    /** The chunks of arrivals published together in the current phase, last first, linked by {@link ArrivalChunk#below}. */
    private final AtomicReference<ArrivalChunk> chunks = new AtomicReference<>();
    /** Participants parked in an idle busy-wait iteration instead of arriving, last first: the next arrival wakes them. */
    private final AtomicReference<Spinner> spinners = new AtomicReference<>();

    /** A park ({@code ticket}) of a participant in an idle busy-wait iteration (MASL §5), on a stack. */
    private record Spinner(Agent agent, long ticket, Spinner below) {
    }

    SynchronisationBarrier(Entry domain) {
        this.domain = domain;
    }

    /**
     * The arrival of a participant, which has issued the ticket of its park; no lock. Returns the
     * phase it completed, which the caller must then trip under the coordinator's lock if it
     * {@link #completes} it still, or -1 if participants remain unarrived: it stays parked until
     * the trip.
     */
    int arrive(Agent agent) {
        Agent top;
        do {
            top = arrivals.get();
            agent.nextArrival = top;
        } while (!arrivals.compareAndSet(top, agent));
        long next = countArrived(1, agent);
        agent.arrivedAt = this;
        agent.arrivalPhase = phase(next);
        return completedPhase(next);
    }

    /**
     * The arrivals of a chunk's participants at once, as {@link #arrive} on each in turn, but with
     * one publication: the chunk goes on a stack of its own, whole, and the trip lets it go whole.
     * Each agent has issued the ticket of its park, and was marked as arrived here in
     * {@code chunk.phase} when its arrival was held ({@link #markArrival}). Returns the phase they
     * completed, or -1.
     */
    int arriveAll(ArrivalChunk chunk) {
        int phase = chunk.phase;
        if (phase(state.get()) != phase) {
            throw new IllegalStateException(describe(state.get()) + ": a chunk of " + chunk.count + " held in phase "
                    + phase + ", which tripped without it");
        }
        ArrivalChunk top;
        do {
            top = chunks.get();
            chunk.below = top;
        } while (!chunks.compareAndSet(top, chunk));
        long next = countArrived(chunk.count, chunk.arrival(0));
        if (phase(next) != phase) {
            throw new IllegalStateException(describe(next) + ": a chunk of " + chunk.count + " arrived in phase "
                    + phase + ", which tripped without it");
        }
        return completedPhase(next);
    }

    /**
     * Marks {@code agent}, a participant whose arrival is held to be published in a chunk, as
     * arrived in {@code phase}, the current one, which cannot move on before the chunk is counted:
     * its arrival is missing until then. Marked while the arrival is held, when the agent's state is
     * still in the holding thread's cache, rather than by a second pass over the chunk.
     */
    void markArrival(Agent agent, int phase) {
        // Read before written: a reference stored into an agent costs G1 a card mark (see ArrivalChunk).
        if (agent.arrivedAt != this) {
            agent.arrivedAt = this;
        }
        agent.arrivalPhase = phase;
    }

    /** The current phase; no lock. */
    int phase() {
        return phase(state.get());
    }

    /** Counts {@code count} arrivals in the current phase, pushed already; returns the state after. */
    private long countArrived(int count, Agent first) {
        long current;
        long next;
        do {
            current = state.get();
            if (unarrived(current) < count) {
                throw new IllegalStateException(describe(current) + ": " + count + " arrive (" + first
                        + " the first), but fewer participants are unarrived");
            }
            next = current - count * ONE_UNARRIVED;
        } while (!state.compareAndSet(current, next));
        wakeSpinners();
        return next;
    }

    /** Whether a participant has arrived in the current phase; no lock. */
    public boolean hasArrivals() {
        long current = state.get();
        return unarrived(current) < participants(current);
    }

    /**
     * Ends the park {@code ticket} of {@code agent}, a participant that has not arrived, at the next
     * arrival, or at once if a participant has arrived in the current phase already; no lock. No
     * wake-up is lost: the spinner is pushed before the count is read again, and an arrival counts
     * before it takes the spinners. A stale ticket, whose park something else ended, is ignored.
     */
    public void wakeOnArrival(Agent agent, long ticket) {
        Spinner top;
        Spinner pushed;
        do {
            top = spinners.get();
            pushed = new Spinner(agent, ticket, top);
        } while (!spinners.compareAndSet(top, pushed));
        if (hasArrivals()) {
            wakeSpinners();
        }
    }

    private void wakeSpinners() {
        // A plain read first: arrivals in lock-step, the hot path, mostly find no spinner.
        if (spinners.get() == null) {
            return;
        }
        for (Spinner spinner = spinners.getAndSet(null); spinner != null; spinner = spinner.below) {
            spinner.agent.unpark(spinner.ticket);
        }
    }

    /** The phase that a state after arrivals shows complete, or -1 if participants remain unarrived. */
    private static int completedPhase(long state) {
        return unarrived(state) == 0 ? phase(state) : -1;
    }

    /** How many participants it has now; no lock. */
    int participants() {
        return participants(state.get());
    }

    /** Whether {@code phase} is still the current phase, not tripped; no lock. */
    boolean inPhase(int phase) {
        return phase(state.get()) == phase;
    }

    /** Under the lock: whether {@code phase} is the current phase and every participant has arrived in it. */
    boolean completes(int phase) {
        long current = state.get();
        return phase(current) == phase && isComplete(current);
    }

    /** Under the lock: whether every participant has arrived, at least one, so that the barrier must trip. */
    boolean isComplete() {
        return isComplete(state.get());
    }

    /** Under the lock: a new participant, not arrived. */
    void addParticipant() {
        long current;
        do {
            current = state.get();
            if (participants(current) == COUNT_MASK) {
                throw new IllegalStateException(describe(current) + ": more than " + COUNT_MASK + " participants");
            }
        } while (!state.compareAndSet(current, current + ONE_PARTICIPANT + ONE_UNARRIVED));
    }

    /** Under the lock: {@code agent} no longer takes part; if it died after arriving, its arrival stays counted. */
    void removeParticipant(Agent agent) {
        long current;
        long next;
        do {
            current = state.get();
            boolean arrived = agent.arrivedAt == this && agent.arrivalPhase == phase(current);
            next = current - ONE_PARTICIPANT - (arrived ? 0 : ONE_UNARRIVED);
            if (participants(current) == 0 || (!arrived && unarrived(current) == 0)) {
                throw new IllegalStateException(describe(current) + ": " + agent + " leaves, but it does not take part");
            }
        } while (!state.compareAndSet(current, next));
        agent.arrivedAt = null;
    }

    /**
     * Under the lock, when {@link #isComplete()}: starts the next phase and lets the agents that
     * arrived go, in arrival order: each that arrived by itself is given to {@code letGo} (which
     * wakes it), but {@code going}, the completing arrival that trips and goes on running (null if
     * a membership change trips); then each chunk, whole, in publication order, to
     * {@code letChunkGo}. Returns how many agents went on: the participants.
     */
    int trip(Agent going, Consumer<Agent> letGo, Consumer<ArrivalChunk> letChunkGo) {
        long current = state.get();
        if (!isComplete(current)) {
            throw new IllegalStateException(describe(current) + " trips incomplete");
        }
        int participants = participants(current);
        long next = ((long) ((phase(current) + 1) & PHASE_MASK) << PHASE_SHIFT)
                | ((long) participants << PARTICIPANTS_SHIFT) | participants;
        if (!state.compareAndSet(current, next)) {
            throw new IllegalStateException(describe(current) + " changed while it tripped");
        }
        for (Agent agent = inArrivalOrder(arrivals.getAndSet(null)); agent != null; ) {
            Agent following = agent.nextArrival;
            agent.nextArrival = null;
            if (agent != going) {
                letGo.accept(agent);
            }
            agent = following;
        }
        for (ArrivalChunk chunk = inPublicationOrder(chunks.getAndSet(null)); chunk != null; ) {
            ArrivalChunk following = chunk.below;
            chunk.below = null;
            chunk.wave = participants;
            letChunkGo.accept(chunk);
            chunk = following;
        }
        return participants;
    }

    /** Reverses a detached stack of chunks (last published first) in place. */
    private static ArrivalChunk inPublicationOrder(ArrivalChunk lastPublished) {
        ArrivalChunk reversed = null;
        ArrivalChunk chunk = lastPublished;
        while (chunk != null) {
            ArrivalChunk earlier = chunk.below;
            chunk.below = reversed;
            reversed = chunk;
            chunk = earlier;
        }
        return reversed;
    }

    /** Reverses a detached stack (last arrival first) in place. */
    private static Agent inArrivalOrder(Agent lastArrived) {
        Agent reversed = null;
        Agent agent = lastArrived;
        while (agent != null) {
            Agent earlier = agent.nextArrival;
            agent.nextArrival = reversed;
            reversed = agent;
            agent = earlier;
        }
        return reversed;
    }

    private static boolean isComplete(long state) {
        return unarrived(state) == 0 && participants(state) > 0;
    }

    private static int unarrived(long state) {
        return (int) (state & COUNT_MASK);
    }

    private static int participants(long state) {
        return (int) ((state >>> PARTICIPANTS_SHIFT) & COUNT_MASK);
    }

    private static int phase(long state) {
        return (int) (state >>> PHASE_SHIFT);
    }

    private String describe(long state) {
        return "barrier of " + domain.name() + " (phase " + phase(state) + ", "
                + (participants(state) - unarrived(state)) + "/" + participants(state) + " arrived)";
    }

    @Override
    public String toString() {
        return describe(state.get());
    }
}
