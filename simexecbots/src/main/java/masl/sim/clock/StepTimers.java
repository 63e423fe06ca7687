package masl.sim.clock;

import java.util.ArrayList;
import java.util.List;
import java.util.PriorityQueue;

/**
 * Actions due at a physics step: the simulated clock behind {@code sleep} and timeouts. A delay in
 * milliseconds is rounded up to whole steps, so an action never runs early. Actions due at the
 * same step run in the order they were added. Thread-safe.
 */
final class StepTimers {

    private record Timer(long dueStep, long sequence, Runnable action) { }

    private final double stepSeconds;
    private final PriorityQueue<Timer> timers = new PriorityQueue<>((a, b) -> a.dueStep() != b.dueStep()
            ? Long.compare(a.dueStep(), b.dueStep()) : Long.compare(a.sequence(), b.sequence()));
    private long sequence;

    StepTimers(double stepSeconds) {
        this.stepSeconds = stepSeconds;
    }

    /** Adds {@code action}, due {@code delayMillis} of simulated time after step {@code now}. */
    synchronized void add(long now, long delayMillis, Runnable action) {
        long steps = (long) Math.ceil(delayMillis / 1000.0 / stepSeconds - 1e-9);
        timers.add(new Timer(now + Math.max(steps, 0), sequence++, action));
    }

    /** Removes and returns the actions due at or before step {@code now}, in order. */
    synchronized List<Runnable> takeDue(long now) {
        List<Runnable> due = new ArrayList<>();
        while (!timers.isEmpty() && timers.peek().dueStep() <= now) {
            due.add(timers.poll().action());
        }
        return due;
    }

    synchronized boolean isEmpty() {
        return timers.isEmpty();
    }
}
