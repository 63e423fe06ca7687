package masl.runtime.scheduling;

import java.util.List;

/**
 * Parked agents let go together whose wake-up is left to the thread that will run them: the
 * thread that lets them go (a barrier trip) hands over the batch without touching each agent, and
 * each agent is woken where it is then run, so its state does not travel between cores twice per
 * step.
 *
 * <p>From the moment it is let go until {@link #wake} returns, the batch holds a pending wake-up
 * for the deadlock watchdog ({@code Mission}), begun by whoever let it go: its agents are still
 * parked, and look idle, but they will run.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java
 * has no friend packages), and may change without notice.
 */
public interface WokenBatch {

    /**
     * Wakes the batch's agents, in the order they were let go, and adds to {@code runnable} those
     * that are now runnable, which the caller must run (or schedule) each once; then ends the pending
     * wake-up. Called once.
     */
    void wake(List<AgentTask> runnable);

    /** The run of slices that ran the batch's agents last, where they are best run again; null if none. */
    SliceRun home();
}
