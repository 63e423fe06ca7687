package masl.e2e.agents;

import masl.agents.Default;

/**
 * A user's own agent type with an accessor a program polls in an empty {@code while}: {@code opened()}
 * is never true, so the poller spins until the mission's timeout. {@code holdFor(ms)} is a primitive
 * that runs long (a robot's slow move), in the calling agent's thread.
 */
public class Latch extends Default {

    public boolean opened() {
        return false;
    }

    public void holdFor(int millis) throws InterruptedException {
        Thread.sleep(millis);
    }
}
