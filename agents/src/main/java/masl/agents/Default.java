package masl.agents;

import masl.runtime.AgentImplementation;

/**
 * The root agent type (descriptor {@code Default.xml}): every MASL agent type extends it.
 * Primitives: {@code getProxyID}, {@code nop}, {@code log}, {@code logln}, {@code sleep}.
 */
public class Default extends AgentImplementation {

    public int getProxyID() {
        return services().proxyId();
    }

    public void nop() {
        // Takes one instruction and nothing else: its duration is the point (MASL §5).
    }

    public void log(String message) {
        services().log(String.valueOf(message));
    }

    public void logln(String message) {
        services().log(message + "\n");
    }

    public void sleep(long ms) throws InterruptedException {
        services().sleep(ms);
    }
}
