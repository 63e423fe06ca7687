package masl.e2e.agents;

import masl.runtime.AgentImplementation;

/**
 * The root type a user wrote for own-default/crew.masl (own-default/Default.xml): the five primitives
 * of every root, written anew, and two of its own.
 */
public class OwnDefault extends AgentImplementation {

    private int greeted;

    public int getProxyID() {
        return services().proxyId();
    }

    public void nop() {
        // One instruction, nothing else.
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

    /** A greeting from this agent; counted. */
    public String hello(String to) {
        greeted++;
        return "hello " + to + " from " + getProxyID();
    }

    /** How many greetings this agent gave. */
    public int tally() {
        return greeted;
    }
}
