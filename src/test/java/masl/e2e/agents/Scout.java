package masl.e2e.agents;

/** A Worker that can also scan and sweep (workers/Scout.xml): for members a receiver's declared type lacks (MASL 4). */
public class Scout extends Worker {

    public int range = 3;

    /** Synchronous: what the scan found. */
    public int scan() {
        return 7;
    }

    /** Asynchronous: journals the sweep, so a test sees which agent ran it, and gives ten times {@code width}. */
    public int sweep(int width) {
        logln(getProxyID() + " sweeps " + width);
        return 10 * width;
    }
}
