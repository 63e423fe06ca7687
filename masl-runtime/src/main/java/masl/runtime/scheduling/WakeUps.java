package masl.runtime.scheduling;

import java.util.concurrent.atomic.AtomicLong;
import masl.runtime.Mission;

/**
 * What the deadlock watchdog ({@link Mission}) knows of wake-ups: how many were counted so far, and
 * how many are pending (promised by a thread that runs no agent's slice), in one atomic word, so
 * that one read gives both at the same instant. See {@link Mission} for the rules of counting and
 * why the watchdog's looks, built on them, cannot report a deadlock falsely.
 *
 * <p>Not final: tests stall a wake-up between its count and its act, the window the rules close.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public class WakeUps {

    /** The counted wake-ups are the word's high 32 bits (they wrap), the pending ones its low 32 bits. */
    private static final long ONE_COUNTED = 1L << 32;

    private final AtomicLong word = new AtomicLong();

    /** A running agent's slice is about to wake an agent or queue an invocation. */
    public void counted() {
        word.addAndGet(ONE_COUNTED);
    }

    /** A wake-up is promised from outside the agents' slices: counted, and pending until {@link #pendingEnded()}. */
    public void pendingStarted() {
        word.addAndGet(ONE_COUNTED + 1);
    }

    public void pendingEnded() {
        word.decrementAndGet();
    }

    /** Both counts at one instant; equal looks mean that nothing was counted in between. */
    public long look() {
        return word.get();
    }

    public static boolean nonePending(long look) {
        return (int) look == 0;
    }
}
