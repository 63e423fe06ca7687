package masl.runtime.scheduling;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Executor;

/**
 * Runs a mission's agents. The runtime calls {@link #schedule} when an agent becomes runnable
 * (at start, after a barrier trip, a release, a wake-up, a yield); the scheduler must then call
 * {@link AgentTask#runSlice()} once, on one of its threads. An agent is never scheduled again
 * before that slice has returned.
 *
 * <p>The runtime makes no arbitrary choice of its own: a scalar block is run by its first arrival,
 * entry barriers release in arrival order, a trip wakes its agents in arrival order. The only
 * source of non-determinism is therefore the order and interleaving in which a scheduler runs
 * slices, and the clock behind {@link #scheduleAfter}: {@link SeededScheduler} (one thread, a
 * seeded order, virtual time) makes a whole mission reproducible.
 *
 * <p>One scheduler runs one mission.
 */
public interface Scheduler {

    /**
     * Starts running these agents: each is runnable once, as if {@link #schedule}d, in the order
     * given. Called once, before any {@code schedule}; no slice may start before every agent has
     * been made runnable (a seeded order must not depend on how fast the caller is).
     */
    void start(List<? extends AgentTask> agents);

    /**
     * The mission clock in nanoseconds, as trace timestamps read it: {@link System#nanoTime()}
     * unless the scheduler keeps a virtual time. Called under the runtime's locks: must not block.
     */
    default long nanoTime() {
        return System.nanoTime();
    }

    /** Makes the agent runnable: its {@code runSlice} is to be called once, soon. */
    void schedule(AgentTask agent);

    /**
     * Makes these agents runnable, as {@link #schedule} on each in this order would: the wave a
     * barrier trip or a release lets go, which a scheduler may take in one pass. The list is
     * the caller's, to be read during the call only.
     */
    default void scheduleAll(List<? extends AgentTask> agents) {
        agents.forEach(this::schedule);
    }

    /**
     * Runs {@code work}, which makes many agents runnable ({@link #schedule}) from a thread that
     * runs no slice of this scheduler (a message that lets a wave of agents go on): a scheduler may
     * then wake its threads once for all of them rather than once per agent. Every agent made
     * runnable in {@code work} has its slice run, as if {@code schedule}d outside it; a slice may
     * start before {@code work} returns. By default, runs {@code work}.
     */
    default void together(Runnable work) {
        work.run();
    }

    /**
     * Makes the agents of a batch that a trip let go runnable: by default wakes them now and
     * {@link #scheduleAll}s those woken; a scheduler whose threads run slices in runs leaves the
     * wake-up to the thread that runs them.
     */
    default void scheduleWoken(WokenBatch batch) {
        int count = batch.wake();
        List<AgentTask> runnable = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            runnable.add(batch.runnable(i));
        }
        scheduleAll(runnable);
    }

    /**
     * The run of slices the calling thread is in, to which a slice may defer effects that only
     * other agents wait for (see {@link SliceRun}); null if the caller is not one of this
     * scheduler's threads, or if the scheduler defers nothing (the default): every effect then
     * happens within its slice, as a seeded order needs.
     */
    default SliceRun currentRun() {
        return null;
    }

    /**
     * Runs the body of a launched asynchronous primitive (MASL §9). By default on one of
     * {@code threads}, concurrently with the agents and free to block for as long as it acts. A
     * scheduler that orders a whole mission itself (seeded, simulated) runs it as one of its own
     * tasks instead, a {@link PrimitiveTurn}, so that when it completes is reproducible too.
     *
     * @param body    runs the primitive and completes its future, which wakes its waiters
     * @param threads the mission's primitive threads
     * @throws java.util.concurrent.RejectedExecutionException if the mission has ended
     */
    default void runPrimitive(Runnable body, Executor threads) {
        threads.execute(body);
    }

    /** Runs {@code action} (quick, non-blocking) after {@code delayMillis} of mission time. */
    void scheduleAfter(long delayMillis, Runnable action);

    /**
     * How many step boundaries an agent may pass in one slice before it yields its thread to other
     * agents; {@link Integer#MAX_VALUE} when agents have threads of their own. The same for the
     * scheduler's whole life: each agent reads it once, when it is made.
     */
    int stepsPerSlice();

    /** Stops every thread of this scheduler, interrupting blocked primitives and sleeps. */
    void shutdown();
}
