package masl.e2e.agents;

/** A Worker that can also scan (workers/Scout.xml): for calls a receiver's declared type lacks (MASL 4). */
public class Scout extends Worker {

    /** Synchronous: what the scan found. */
    public int scan() {
        return 7;
    }
}
