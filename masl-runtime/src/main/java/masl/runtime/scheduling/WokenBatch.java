package masl.runtime.scheduling;

/**
 * Parked agents let go together whose wake-up is left to the thread that will run them: the
 * thread that lets them go (a barrier trip) hands over the batch without touching each agent, and
 * each agent is woken where it is then run, so its state does not travel between cores twice per
 * step.
 *
 * <p>From the moment it is let go until {@link #wake} returns, the batch holds a pending wake-up
 * for the deadlock watchdog ({@code Mission}), begun by whoever let it go: its agents are still
 * parked, and look idle, but they will run.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java
 * has no friend packages), and may change without notice.
 */
public interface WokenBatch {

    /**
     * Wakes the batch's agents, in the order they were let go, and returns how many are now
     * runnable: {@link #runnable}{@code (0)} up to that number less one, in that order, which the
     * caller must run (or schedule) each once. Then ends the pending wake-up. Called once.
     *
     * <p>The runnable agents stay in the batch: a batch lives for one step, so its array is in the
     * young generation, and filling it writes no reference into long-lived memory. A reference stored
     * there (a list kept from batch to batch) costs G1 a card mark, a fence and later a refinement
     * thread's scan per agent per step (at 100,000 agents).
     */
    int wake();

    /** The {@code index}th agent {@link #wake} made runnable. */
    AgentTask runnable(int index);

    /** The run of slices that ran the batch's agents last, where they are best run again; null if none. */
    SliceRun home();

    /**
     * How many agents the trip that let the batch go let go in all, this batch's among them: a
     * scheduler shares the batches of a long wave among its threads, and runs those of a short one
     * where they were let go.
     */
    int wave();

    /**
     * Wakes the batch's agents and runs the slice of each that is runnable, on the calling thread,
     * in the order they were let go; returns how many slices it ran. Called once, instead of
     * {@link #wake}, by a thread that runs the batch itself. By default wakes them all, then runs
     * them; a batch may instead wake each agent straight into its slice
     * ({@link Slices#wokenSlice}).
     */
    default int run(Slices slices) {
        int runnable = wake();
        for (int i = 0; i < runnable; i++) {
            slices.slice(runnable(i));
        }
        return runnable;
    }

    /** How the thread running a batch runs one slice, so that it knows meanwhile whose slice it runs. */
    interface Slices {
        /** Runs the slice of a runnable agent. */
        void slice(AgentTask agent);

        /** {@link AgentTask#runSliceWoken}: ends the park {@code ticket} and runs the slice, or false. */
        boolean wokenSlice(AgentTask agent, long ticket);
    }
}
