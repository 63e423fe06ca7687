package masl.runtime.entry;

import java.util.Arrays;
import java.util.function.Function;
import masl.runtime.Agent;
import masl.runtime.Mission;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.SliceRun;

/**
 * The arrivals at synchronisation barriers that the slices run by one scheduler thread defer to
 * it ({@link SliceRun}): published together, one push and one count for all the arrivals at one
 * barrier since the last flush, instead of two contended atomic updates per agent. In lock-step,
 * where every agent arrives once per step, that is most of the cost of a step the threads would
 * otherwise pay to each other.
 *
 * <p>Arrivals at one barrier collect in arrival order; an arrival at another barrier flushes those
 * first. An agent whose arrival waits here is parked, and stays a participant: nothing but its own
 * program removes a participant that is not held by an entry or exit barrier, so the phase cannot
 * trip without it, and the arrival counts in the phase it was made in, in which the agent is marked
 * as arrived when it comes here ({@link SynchronisationBarrier#markArrival}). The flush that completes the
 * phase trips it, as a membership change does, waking every arrived agent.
 *
 * <p>Deadlock watchdog (the mission's {@code DeadlockWatchdog}): from the first arrival held to the end of the flush, a
 * wake-up is pending: the parked agents look idle, but the flush may trip their barrier.
 *
 * <p>Confined to its thread.
 */
final class ArrivalCombiner implements SliceRun.Deferred {

    /** Room for the arrivals of the smallest flush's worth of slices. */
    private static final int FIRST_CAPACITY = SliceRun.DEFAULT_SLICES_PER_FLUSH;
    /** The most room a chunk is given before its arrivals come; more grows it. */
    private static final int MAX_CAPACITY = 256;
    /**
     * Chunks each thread should publish per phase ({@link #slicesPerFlush}): enough for a thread
     * with nothing left to take a share of another's, few enough that their publications and the
     * trip's hand-over of each, a handful of cache lines both threads write, cost little per step
     * even where the cores are far apart (about a microsecond for each line that crosses).
     */
    static final int CHUNKS_PER_THREAD = 2;
    /**
     * The participants from which a chunk's wake-up warms its agents first ({@link Agent#warmUp}):
     * below, the state of the agents a core ran is still in its cache, and the reads only cost.
     * Measured on two workers with 512 KB of L2 cache each (a measurement, not kept in docs/performance.md):
     * without warming, 1,000 and 3,000 agents stepped 11% faster; with it, 10,000 agents 10% and
     * 100,000 agents 16% faster.
     */
    static final int WARM_FROM = 4_096;

    private final EntryCoordinator coordinator;
    private final Mission mission;
    private final SliceRun run;
    /** The thread whose run it is: it is made on that thread, at the run's first deferred arrival. */
    private final Thread thread = Thread.currentThread();
    private SynchronisationBarrier barrier;
    /** The phase of {@link #barrier} the held arrivals count in. */
    private int phase;
    /** The arrivals held, in arrival order, in {@code held[0]} to {@code held[count - 1]}; a new array for each chunk. */
    private Agent[] held;
    private int count;
    /** The barrier of the latest publication; null before the first. */
    private SynchronisationBarrier published;
    /** The arrivals per chunk {@link #slicesPerFlush} asked for last: the room a new chunk is given. */
    private int expected;
    /** The participants {@link #slicesPerFlush} found last at the barrier of the latest publication. */
    private int participants;
    /** The barrier of the latest publication that completed no phase, and that phase; null if none. */
    private SynchronisationBarrier awaited;
    private int awaitedPhase;

    ArrivalCombiner(EntryCoordinator coordinator, Mission mission, SliceRun run) {
        this.coordinator = coordinator;
        this.mission = mission;
        this.run = run;
    }

    /**
     * The combiner of the calling thread's run of slices, made by {@code create} on first use, or
     * null if {@code scheduler} runs no runs: the one that held the agent's latest arrival if it is
     * the calling thread's (an agent mostly stays on its worker from step to step), else the
     * scheduler's. In lock-step every agent-step arrives, and the scheduler's way (its thread, its
     * worker, the run's deferred work) was a tenth of an agent-step.
     */
    static ArrivalCombiner ofCallingThread(MemberAgent agent, Scheduler scheduler,
            Function<SliceRun, ArrivalCombiner> create) {
        ArrivalCombiner last = agent.heldBy;
        if (last != null && last.thread == Thread.currentThread()) {
            return last;
        }
        SliceRun run = scheduler.currentRun();
        if (run == null) {
            return null;
        }
        ArrivalCombiner combiner = (ArrivalCombiner) run.deferred(create);
        agent.heldBy = combiner;
        return combiner;
    }

    /** Holds the arrival of {@code agent}, which has issued the ticket of its park, at {@code at}. */
    void arrive(Agent agent, SynchronisationBarrier at) {
        if (count > 0 && at != barrier) {
            flush();
        }
        if (count == 0) {
            // Before the agent turns PARKED: the watchdog must not take it for idle for good.
            mission.outsideWakeUpStarted();
            barrier = at;
            // Participants that have not arrived keep the phase from tripping: it is theirs until published.
            phase = at.phase();
            held = new Agent[Math.max(FIRST_CAPACITY, Math.min(expected, MAX_CAPACITY))];
        } else if (count == held.length) {
            held = Arrays.copyOf(held, 2 * count);
        }
        at.markArrival(agent, phase);
        held[count++] = agent;
    }

    @Override
    public boolean flush() {
        if (count == 0) {
            return false;
        }
        SynchronisationBarrier arrivedAt = barrier;
        published = arrivedAt;
        ArrivalChunk chunk = new ArrivalChunk(held, count, run, mission, participants >= WARM_FROM);
        chunk.phase = phase;
        barrier = null;
        held = null;
        count = 0;
        try {
            int completedPhase = arrivedAt.arriveAll(chunk);
            if (completedPhase >= 0) {
                awaited = null;
                coordinator.tripCompleted(arrivedAt, completedPhase);
            } else {
                awaited = arrivedAt;
                awaitedPhase = chunk.phase;
            }
        } finally {
            mission.outsideWakeUpEnded();
        }
        return true;
    }

    /**
     * A phase's arrivals in {@value #CHUNKS_PER_THREAD} chunks per thread: the participants of the
     * barrier of the latest publication, shared among {@code threads}, in that many chunks (a
     * mission with no publication yet asks the default). Each chunk's publication and trip update
     * words that every thread writes (the barrier's count and stack, the home queue, the watchdog's
     * count): where the cache line of such a word takes 300–700 ns to move between the two cores,
     * chunks of 32 halved lock-step at 1,000 agents (measured on two workers).
     */
    @Override
    public int slicesPerFlush(int threads) {
        SynchronisationBarrier last = published;
        if (last == null) {
            return SliceRun.DEFAULT_SLICES_PER_FLUSH;
        }
        participants = last.participants();
        expected = participants / (CHUNKS_PER_THREAD * threads);
        return expected;
    }

    @Override
    public boolean awaitsOthers() {
        return awaited != null && awaited.inPhase(awaitedPhase);
    }
}
