package masl.runtime;

/** An agent as a scheduler sees it: something to run, one slice at a time. */
public interface AgentTask {

    /** The agent's proxy id: 0, 1, 2, … dense, so schedulers may index by it. */
    int id();

    /**
     * Runs the agent's program until it suspends or finishes. The scheduler calls it once per
     * {@link Scheduler#schedule} call, never concurrently for one agent.
     */
    void runSlice();

    /** Whether the agent's program has finished (it will not be scheduled again). */
    boolean finished();
}
