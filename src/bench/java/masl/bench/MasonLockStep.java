package masl.bench;

import java.util.concurrent.Callable;
import sim.engine.Schedule;
import sim.engine.Sequence;
import sim.engine.SimState;
import sim.engine.Steppable;

/**
 * The peer a user would pick: MASON 14, the standard Java library for stepping many agents in lock-step,
 * with the same trivial step as the other columns ({@code i++}). One step is one tick of MASON's
 * {@link Schedule} on the calling thread.
 *
 * <ul>
 *   <li>{@link #schedule()}: each agent {@code scheduleRepeating} on the schedule, as a MASON model
 *       is usually written (the schedule's heap orders the agents anew at every tick);</li>
 *   <li>{@link #sequence()}: one {@link Sequence} of all the agents scheduled once, repeating, so
 *       a tick is one loop over an array on one thread: the floor of a trivial agent-step.</li>
 * </ul>
 */
final class MasonLockStep implements LockStepRun {

    private final String name;
    private final boolean oneSequence;

    private MasonLockStep(String name, boolean oneSequence) {
        this.name = name;
        this.oneSequence = oneSequence;
    }

    static MasonLockStep schedule() {
        return new MasonLockStep("MASON Schedule", false);
    }

    static MasonLockStep sequence() {
        return new MasonLockStep("MASON Sequence", true);
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public Callable<Double> prepare(int agents, int steps) {
        SimState state = new SimState(1);
        state.start();
        Counter[] counters = new Counter[agents];
        for (int agent = 0; agent < agents; agent++) {
            counters[agent] = new Counter();
        }
        if (oneSequence) {
            state.schedule.scheduleRepeating(new Sequence(counters));
        } else {
            for (Counter counter : counters) {
                state.schedule.scheduleRepeating(counter);
            }
        }
        // A tick of the one-thread sequence is so short that the other columns' step count would time the JIT.
        int ticks = oneSequence ? steps * 20 : steps;
        return () -> {
            StepClock clock = new StepClock();
            for (int step = 0; step < ticks; step++) {
                state.schedule.step(state);
                clock.stepEnded();
            }
            state.finish();
            return clock.stepsPerSecond();
        };
    }

    /** An agent whose step is the trivial instruction of every column. */
    private static final class Counter implements Steppable {
        private static final long serialVersionUID = 1;
        int i;

        @Override
        public void step(SimState state) {
            i++;
        }
    }
}
