package masl.runtime.scheduling;

/**
 * A scheduler that keeps the mission's time itself (virtual milliseconds) and orders every task
 * on it, so that primitives' sleeps and call time limits are counted on that clock rather than in
 * real time ({@link ClockedCall}): a seed then names one run, limits included.
 */
public interface MissionClock {

    /** The mission's time now, in milliseconds. */
    long millis();

    /**
     * Moves the clock on to {@code until} while a call holds the run (a primitive called in an
     * agent's slice sleeps): nothing else runs meanwhile, and timers due before it fire after the
     * call, in their order.
     */
    void passHeld(long until);

    /** Makes {@code task} runnable, drawn like any other task, when the clock reaches {@code at}. */
    void runAt(long at, Runnable task);
}
