package masl.runtime.scheduling;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinWorkerThread;
import java.util.concurrent.locks.LockSupport;

/** A worker of one {@link PoolScheduler}'s pool: lets {@link Blocking} find the runner it runs, and its run of slices. */
final class PoolWorker extends ForkJoinWorkerThread implements WokenBatch.Slices {
    final PoolScheduler scheduler;
    final SliceRun run = new SliceRun();
    /** Set by whoever takes the worker off the idle list to wake it. */
    volatile boolean woken;
    /** Whether its runner is in {@code PoolScheduler.runUntilEmpty}, and so takes what comes to its home queue before it goes idle. */
    boolean inRun;
    /** Blocking calls ({@link Blocking}) the worker is in: its runner is not counted meanwhile. */
    int blockedCalls;
    /** The agent whose slice the worker runs, null between slices. */
    AgentTask running;
    /** The hand-over slot: an agent a slice made runnable, which this worker runs next. */
    private AgentTask next;
    /** Slices run in a row from the slot. */
    private int handedOverInARow;

    PoolWorker(ForkJoinPool pool, PoolScheduler scheduler) {
        super(pool);
        this.scheduler = scheduler;
    }

    void wake() {
        woken = true;
        LockSupport.unpark(this);
    }

    @Override
    public void slice(AgentTask agent) {
        PoolScheduler.runSlice(this, agent);
    }

    @Override
    public boolean wokenSlice(AgentTask agent, long ticket) {
        running = agent;
        try {
            return agent.runSliceWoken(ticket);
        } finally {
            running = null;
        }
    }

    /**
     * Takes {@code agent}, made runnable by the slice this worker runs, into the hand-over slot,
     * unless the agent is the slice's own (a slice that yields goes behind the others), the slot
     * is taken, the worker blocks in a primitive, or it has run {@value PoolScheduler#HAND_OVERS} slices from
     * the slot in a row: agents that take turns (an invocation and its answer) then stay on one
     * core, without a trip through the common queue that the other runner contends for. True if
     * it took it.
     */
    boolean handsOver(AgentTask agent) {
        if (running == null || agent == running || next != null || blockedCalls > 0
                || handedOverInARow >= PoolScheduler.HAND_OVERS) {
            return false;
        }
        next = agent;
        return true;
    }

    /** The agent in the slot, now taken out of it, or null; counts the slices run from it in a row. */
    AgentTask takeHandOver() {
        AgentTask agent = next;
        if (agent == null) {
            handedOverInARow = 0;
            return null;
        }
        next = null;
        handedOverInARow++;
        return agent;
    }

    @Override
    protected void onTermination(Throwable exception) {
        scheduler.releaseHandOver(this);
        run.closed = true;
        scheduler.moveToCommonQueue(run);
        scheduler.runs.remove(run);
        if (!scheduler.runQueue.isEmpty()) {
            scheduler.startRunnerIfNeeded();
        }
        super.onTermination(exception);
    }
}
