package masl.runtime.scheduling;

import java.util.concurrent.atomic.AtomicLongArray;
import masl.runtime.Mission;

/**
 * What the deadlock watchdog ({@link Mission}) knows of wake-ups: how many were counted so far, and
 * how many are pending (promised by a thread that runs no agent's slice), as if in one atomic word,
 * so that one {@link #look} gives both at the same instant. See {@link Mission} for the rules of
 * counting and why the watchdog's looks, built on them, cannot report a deadlock falsely.
 *
 * <p><b>Striped by thread.</b> A lock-step pass counts four times per chunk of arrivals (the chunk's
 * first held arrival, its publication, its trip, its wake-up), from every worker: one word that both
 * workers write crosses between the cores at each update. So each thread updates a word of its own
 * stripe (by its id; two threads may share one), and a look reads the stripes twice until both
 * reads agree. Each stripe's word only changes by an update that counts (its high bits grow) or by
 * the end of a pending wake-up (its low bits fall), so a stripe read equal twice did not change in
 * between, and all of them were, at one instant between the two reads, what the look returns: the
 * sum of the words, whose high bits are the counted wake-ups and whose low bits the pending ones, as
 * the one word held them (a stripe's pending count may fall below zero, the wake-up having begun on
 * another thread, and borrows from its counted bits, which the sum gives back).
 *
 * <p>Not final: tests stall a wake-up between its count and its act, the window the rules close.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public class WakeUps {

    /** The counted wake-ups are a word's high 32 bits (they wrap), the pending ones its low 32 bits. */
    private static final long ONE_COUNTED = 1L << 32;
    private static final int STRIPES = 8;
    /** Longs from one stripe's word to the next: 128 bytes, so that no two share a cache line. */
    private static final int SPACING = 16;
    /** Two reads of the stripes that disagree this many times in a row make a look that cannot be quiet. */
    private static final int READS = 16;

    private final AtomicLongArray words = new AtomicLongArray(STRIPES * SPACING);

    /** A running agent's slice is about to wake an agent or queue an invocation. */
    public void counted() {
        words.getAndAdd(ownStripe(), ONE_COUNTED);
    }

    /** A wake-up is promised from outside the agents' slices: counted, and pending until {@link #pendingEnded()}. */
    public void pendingStarted() {
        words.getAndAdd(ownStripe(), ONE_COUNTED + 1);
    }

    public void pendingEnded() {
        words.getAndDecrement(ownStripe());
    }

    private static int ownStripe() {
        return ((int) Thread.currentThread().getId() & (STRIPES - 1)) * SPACING;
    }

    /**
     * Both counts at one instant; equal looks mean that nothing was counted in between. If the
     * stripes keep changing while it reads them, a look that says a wake-up is pending, which the
     * watchdog never takes for quiet.
     */
    public long look() {
        long[] first = new long[STRIPES];
        for (int read = 0; read < READS; read++) {
            long sum = 0;
            boolean agree = true;
            for (int stripe = 0; stripe < STRIPES; stripe++) {
                long word = words.get(stripe * SPACING);
                agree &= read > 0 && word == first[stripe];
                first[stripe] = word;
                sum += word;
            }
            if (agree) {
                return sum;
            }
        }
        return 1;
    }

    public static boolean nonePending(long look) {
        return (int) look == 0;
    }
}
