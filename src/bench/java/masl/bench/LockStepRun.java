package masl.bench;

import java.util.concurrent.Callable;

/** One way of running N agents through a number of lock-step steps. */
interface LockStepRun {

    String name();

    /**
     * Everything that is not the run itself (translating, compiling, allocating), done before the
     * clock starts; the returned call runs the agents and returns their steps per second, timed by
     * a {@link StepClock}.
     */
    Callable<Double> prepare(int agents, int steps) throws Exception;
}
