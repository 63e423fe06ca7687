package masl.runtime;

/**
 * What the runtime offers to the Java implementation of an agent type: its identity, the mission
 * journal and the agent's clock. One instance per agent, bound before the agent's program starts.
 */
public interface AgentServices {

    /** The agent's proxy id: 0, 1, 2, … in declaration order (MASL §4). */
    int proxyId();

    /** Appends {@code text} to the mission journal in one atomic write (MASL §13). */
    void log(String text);

    /**
     * Pauses the agent for {@code ms} milliseconds of mission time (simulated time in SimExecBots).
     *
     * @throws InterruptedException when the mission is stopped meanwhile
     */
    void sleep(long ms) throws InterruptedException;
}
