package masl.runtime.scheduling;

/** An agent as a scheduler sees it: something to run, one slice at a time. */
public interface AgentTask {

    /** The agent's proxy id: 0, 1, 2, … dense, so schedulers may index by it. */
    int id();

    /**
     * Runs the agent's program until it suspends or finishes, or serves the invocations of a
     * blocked or finished agent. The scheduler calls it once per {@link Scheduler#schedule} call;
     * the runtime never schedules an agent again before that call has returned.
     */
    void runSlice();

    /**
     * Ends the park {@code ticket} of the agent and runs its slice at once, on the calling thread,
     * which holds a pending wake-up for it (see {@link WokenBatch}): true if it did; false, and
     * nothing changed, if the agent is not parked with that ticket. By default false: the caller
     * then wakes it as any other.
     */
    default boolean runSliceWoken(long ticket) {
        return false;
    }
}
