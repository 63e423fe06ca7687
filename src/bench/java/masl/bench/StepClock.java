package masl.bench;

/**
 * Times the steps of a lock-step run from the end of its first step to the end of its last, so
 * the rate compares steady states: creating threads, agents and first waves is left out, and is
 * paid once per mission, not per step.
 */
final class StepClock {

    private long steps;
    private long firstEnd;
    private long lastEnd;

    /** Called once per step, by whoever completes it (the barrier's last arrival). */
    synchronized void stepEnded() {
        long now = System.nanoTime();
        if (steps++ == 0) {
            firstEnd = now;
        }
        lastEnd = now;
    }

    /** Steps per second after the first step; needs at least two steps. */
    synchronized double stepsPerSecond() {
        if (steps < 2) {
            throw new IllegalStateException("a rate needs two steps, got " + steps);
        }
        return (steps - 1) / ((lastEnd - firstEnd) / 1e9);
    }
}
