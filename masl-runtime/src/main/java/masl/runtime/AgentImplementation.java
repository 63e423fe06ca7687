package masl.runtime;

/**
 * Base class of every agent type's Java implementation ({@code masl.agents.Default} extends it,
 * and every type extends {@code Default}). The runtime binds the agent's {@link AgentServices}
 * once, before the agent's program starts; a primitive reaches the mission through them.
 */
public abstract class AgentImplementation {

    private volatile AgentServices services;

    /**
     * Binds this implementation to the agent that runs it.
     *
     * @throws IllegalStateException if it is already bound: one implementation object, one agent
     */
    public final void bind(AgentServices agentServices) {
        if (agentServices == null) {
            throw new NullPointerException("agentServices");
        }
        if (services != null) {
            throw new IllegalStateException("agent implementation already bound to agent " + services.proxyId());
        }
        services = agentServices;
    }

    /**
     * The services of the agent running this implementation.
     *
     * @throws IllegalStateException if called before the runtime bound it
     */
    protected final AgentServices services() {
        AgentServices bound = services;
        if (bound == null) {
            throw new IllegalStateException("agent implementation used outside a mission");
        }
        return bound;
    }

    /**
     * The proxy id of the agent {@code agent} runs for: generated type tests on an agent of any type
     * (MASL §4) ask it, whatever class the type's root names.
     *
     * @throws IllegalStateException if {@code agent} is not bound to an agent yet
     */
    public static int proxyIdOf(AgentImplementation agent) {
        return agent.services().proxyId();
    }
}
