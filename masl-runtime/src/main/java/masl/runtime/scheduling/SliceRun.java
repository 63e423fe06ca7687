package masl.runtime.scheduling;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.function.Function;

/**
 * The run of slices that one thread of a {@link Scheduler} goes through, and the work its slices
 * defer to the thread: effects that only <em>other</em> agents wait for (an arrival at a
 * synchronisation barrier) may be left to the thread, which then does those of many slices at
 * once, one publication instead of one per slice, where the scheduler's threads would contend for
 * the same word.
 *
 * <p><b>Contract of the scheduler</b> that hands out a run ({@link Scheduler#currentRun}): it
 * {@linkplain #flush flushes} the run after a bounded number of slices, before its thread blocks
 * (see {@link Blocking}) and before it goes idle. So a deferred effect comes later than its slice,
 * but within the same run of slices, as if that slice had been slower; nobody who depends on it
 * waits for anything else first.
 *
 * <p><b>Contract of the slice</b> that defers: its agent must not run again before the effect is
 * done (an agent parked until others arrive after it), and it tells the deadlock watchdog that a
 * wake-up may be pending until then.
 *
 * <p>Confined to its thread.
 */
public final class SliceRun {

    /** Work deferred to a thread's run of slices. */
    public interface Deferred {
        /** Does the work deferred so far; true if there was any (agents may have been made runnable). */
        boolean flush();

        /**
         * Whether agents whose work this run published are parked until other agents, running
         * elsewhere, do theirs (the phase of a barrier they arrived at has not tripped yet): the
         * thread may then expect work back soon.
         */
        boolean awaitsOthers();

        /**
         * How many slices the thread should run between two flushes, when its scheduler has
         * {@code threads} threads running slices; the scheduler keeps it within its own bounds.
         * Asked after each flush. By default {@link #DEFAULT_SLICES_PER_FLUSH}.
         */
        default int slicesPerFlush(int threads) {
            return DEFAULT_SLICES_PER_FLUSH;
        }
    }

    /** The slices between two flushes that deferred work asks for unless it says otherwise. */
    public static final int DEFAULT_SLICES_PER_FLUSH = 32;

    private Deferred deferred;
    /**
     * Batches whose agents this run ran last, for its thread to run first (a {@link PoolScheduler}
     * worker's); others take them when they have nothing else. Once the thread has ended
     * ({@link #closed}), whatever comes here is moved on to the scheduler's common queue.
     */
    final ConcurrentLinkedQueue<WokenBatch> homeQueue = new ConcurrentLinkedQueue<>();
    volatile boolean closed;

    /**
     * The run's deferred work, made by {@code create} on first use. One scheduler runs one mission,
     * whose runtime makes one kind of deferred work, so every caller gets what its own
     * {@code create} makes.
     */
    public Deferred deferred(Function<SliceRun, ? extends Deferred> create) {
        if (deferred == null) {
            deferred = create.apply(this);
        }
        return deferred;
    }

    /** {@link Deferred#awaitsOthers()} of the run's deferred work; false if there is none. */
    public boolean awaitsOthers() {
        return deferred != null && deferred.awaitsOthers();
    }

    /** {@link Deferred#slicesPerFlush} of the run's deferred work; the default if there is none yet. */
    public int slicesPerFlush(int threads) {
        return deferred == null ? DEFAULT_SLICES_PER_FLUSH : deferred.slicesPerFlush(threads);
    }

    /** Does the deferred work; true if there was any. */
    public boolean flush() {
        return deferred != null && deferred.flush();
    }
}
