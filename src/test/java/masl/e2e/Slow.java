package masl.e2e;

/**
 * Called by its full name from an entry test, it holds the testing agent's thread for a while: the
 * way to make one agent late to {@code main} under the pool or a thread per agent, where a fast
 * agent used to run its whole program before the late one had even tested {@code main}.
 */
public final class Slow {

    private Slow() {
    }

    /** Sleeps {@code ms} if {@code slow}; always true, so it can stand in a test. */
    public static boolean pause(boolean slow, long ms) {
        if (slow) {
            try {
                Thread.sleep(ms);
            } catch (InterruptedException interrupted) {
                Thread.currentThread().interrupt();
            }
        }
        return true;
    }
}
