package masl.runtime;

import java.util.Arrays;

/**
 * Memory kept back for the end of a mission that exhausts the heap. A program whose data grows for
 * ever ends with an {@code OutOfMemoryError} in whichever thread allocates next; then every thread
 * would fail in turn, the timeout's and the signals' included, and the trace would lose its end. So
 * a block of the heap is held from the first mission on: the first {@code OutOfMemoryError} an
 * agent, a primitive or any thread reports ({@link #exhausted}) releases it and fails the running
 * missions, which end as after any failure (their {@code mission-ended} record, their report) in
 * the room it leaves. <b>Internal:</b> not part of the API.
 */
public final class MemoryReserve {

    /** A sixteenth of the heap, at most 16 MiB: room to end a mission, not to run one. */
    private static final int SIZE = (int) Math.min(16L << 20, Runtime.getRuntime().maxMemory() / 16);

    private static volatile byte[] block;
    /** What fails each running mission; an array, so that {@link #exhausted} walks it without allocating. */
    private static volatile Runnable[] missions = new Runnable[0];

    private MemoryReserve() {
    }

    /** Holds the block again if a mission before used it up. */
    static void hold() {
        if (block == null) {
            synchronized (MemoryReserve.class) {
                if (block == null) {
                    block = new byte[SIZE];
                }
            }
        }
    }

    /** {@code whenExhausted} runs when the heap is exhausted, until {@link #forget} is given it. */
    static synchronized void watch(Runnable whenExhausted) {
        Runnable[] more = Arrays.copyOf(missions, missions.length + 1);
        more[missions.length] = whenExhausted;
        missions = more;
    }

    static synchronized void forget(Runnable whenExhausted) {
        missions = Arrays.stream(missions).filter(watcher -> watcher != whenExhausted).toArray(Runnable[]::new);
    }

    /**
     * The heap is exhausted ({@code OutOfMemoryError} was thrown): releases the block and fails
     * the running missions. Allocates nothing before the block is released.
     */
    public static void exhausted() {
        block = null;
        Runnable[] running = missions;
        for (int i = 0; i < running.length; i++) {
            running[i].run();
        }
    }
}
