package masl.bench;

import java.util.Arrays;
import java.util.concurrent.atomic.AtomicLong;

/**
 * How far apart two of the machine's cores are now: the time a value takes to go from one thread to
 * another and back through one shared word. On the 2-core virtual machines the bench runs on, the
 * host places the two CPUs near each other or far apart, and moves them from time to time (a round
 * trip of 65-150 ns against 330-700 ns). Two lock-step workers, which exchange a
 * few cache lines per chunk of agents, run slower when they are far; MASON's one thread does not
 * notice. The lock-step section prints it beside each row, so that a reader knows which kind of run
 * the row was.
 */
final class CoreDistance {

    private static final int TRIPS = 20_000;
    private static final int PROBES = 5;
    /** A probe on a loaded machine, whose partner thread may wait for a CPU, gives up after this long. */
    private static final long PROBE_LIMIT_NANOS = 1_000_000_000L;
    private static final long GIVE_UP = -1;

    private CoreDistance() {
    }

    /** The median of a few probes' round trips, in nanoseconds; -1 on one CPU, or if a probe gave up. */
    static long roundTripNanos() throws InterruptedException {
        if (Runtime.getRuntime().availableProcessors() < 2) {
            return GIVE_UP;
        }
        long[] probes = new long[PROBES];
        for (int i = 0; i < PROBES; i++) {
            probes[i] = probe();
            if (probes[i] == GIVE_UP) {
                return GIVE_UP;
            }
        }
        Arrays.sort(probes);
        return probes[PROBES / 2];
    }

    /** One probe: {@value #TRIPS} round trips between this thread and a partner, ns per round trip. */
    private static long probe() throws InterruptedException {
        AtomicLong ball = new AtomicLong();
        Thread partner = new Thread(() -> {
            for (long serve = 1; serve < 2L * TRIPS; serve += 2) {
                long seen;
                while ((seen = ball.get()) != serve) {
                    if (seen == GIVE_UP) {
                        return;
                    }
                    Thread.onSpinWait();
                }
                ball.set(serve + 1);
            }
        }, "bench-core-distance");
        partner.setDaemon(true);
        partner.start();
        long start = System.nanoTime();
        long deadline = start + PROBE_LIMIT_NANOS;
        for (long serve = 0; serve < 2L * TRIPS; serve += 2) {
            ball.set(serve + 1);
            while (ball.get() != serve + 2) {
                if (System.nanoTime() - deadline > 0) {
                    ball.set(GIVE_UP);
                    partner.join();
                    return GIVE_UP;
                }
                Thread.onSpinWait();
            }
        }
        long nanos = (System.nanoTime() - start) / TRIPS;
        partner.join();
        return nanos;
    }
}
