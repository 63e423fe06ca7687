package masl.bench;

import java.util.Arrays;

/**
 * The end of each step of a lock-step mission, from the trace's barrier trips: the rate from the end
 * of the first step to the end of the last, as {@link StepClock} gives it, and the rate over the later
 * half of the steps, once a fresh JVM's JIT has compiled what a step runs.
 */
final class TripTimes {

    private long[] ends = new long[1024];
    private int count;

    /** Called once per step, by whoever completes it (the barrier's last arrival). */
    synchronized void tripped() {
        if (count == ends.length) {
            ends = Arrays.copyOf(ends, count * 2);
        }
        ends[count++] = System.nanoTime();
    }

    synchronized int count() {
        return count;
    }

    /** Steps per second after the first step; needs at least two steps. */
    synchronized double stepsPerSecond() {
        return rate(0, count - 1);
    }

    /** Steps per second over the later half of the steps; needs at least three. */
    synchronized double laterStepsPerSecond() {
        return rate(count / 2, count - 1);
    }

    private double rate(int from, int to) {
        if (from < 0 || to <= from) {
            throw new IllegalStateException("a rate needs two steps in its span, got " + count + " steps");
        }
        return (to - from) / ((ends[to] - ends[from]) / 1e9);
    }
}
