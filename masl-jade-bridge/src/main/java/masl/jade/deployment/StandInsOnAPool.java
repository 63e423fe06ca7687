package masl.jade.deployment;

import java.util.ArrayList;
import java.util.List;
import masl.runtime.scheduling.AgentTask;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.SliceRun;
import masl.runtime.scheduling.WokenBatch;

/**
 * The scheduler of a mission with deployed agents: their stand-ins' slices run on a
 * {@link PoolScheduler} (one worker per core), every other agent's as {@code others} runs it (a JADE
 * thread each). A stand-in's slice performs its step's requests and holds no thread between them
 * ({@link StandIn}), so a few workers pass a wave of a thousand deployed agents as they pass
 * in-process agents, where a thread per stand-in cost a thread wake-up per agent and message.
 *
 * <p>Which scheduler runs an agent is fixed at {@link #start}; the runtime schedules an agent once
 * per slice, whichever runs it, so the contract of {@link Scheduler} holds for each. Only the pool's
 * workers have runs ({@link #currentRun}), so only stand-ins' arrivals are held in batches, and a
 * {@link WokenBatch} is always of stand-ins: the pool runs it in its passes. The timer is
 * {@code others}'; both are shut down together.
 */
public final class StandInsOnAPool implements Scheduler {

    private final Scheduler others;
    private final Coordination coordination;
    private final PoolScheduler pool = PoolScheduler.forStepsElsewhere();
    /** Whether the pool runs each agent, by proxy id: written by {@link #start}, before any slice. */
    private volatile boolean[] onPool = new boolean[0];

    /** Runs the stand-ins {@code coordination} made on a pool, the other agents on {@code others}. */
    public StandInsOnAPool(Scheduler others, Coordination coordination) {
        this.others = others;
        this.coordination = coordination;
    }

    @Override
    public void start(List<? extends AgentTask> agents) {
        boolean[] pooled = new boolean[agents.size()];
        List<AgentTask> standIns = new ArrayList<>();
        List<AgentTask> rest = new ArrayList<>();
        for (AgentTask agent : agents) {
            pooled[agent.id()] = coordination.isStandIn(agent.id());
            (pooled[agent.id()] ? standIns : rest).add(agent);
        }
        onPool = pooled;
        others.start(rest);
        pool.start(standIns);
    }

    @Override
    public void schedule(AgentTask agent) {
        if (onPool[agent.id()]) {
            pool.schedule(agent);
        } else {
            others.schedule(agent);
        }
    }

    @Override
    public void scheduleAll(List<? extends AgentTask> agents) {
        boolean[] pooled = onPool;
        List<AgentTask> standIns = new ArrayList<>(agents.size());
        List<AgentTask> rest = new ArrayList<>();
        for (AgentTask agent : agents) {
            (pooled[agent.id()] ? standIns : rest).add(agent);
        }
        pool.scheduleAll(standIns);
        others.scheduleAll(rest);
    }

    /** Stand-ins a container's message lets go on: the pool's workers are woken once for all. */
    @Override
    public void together(Runnable work) {
        pool.together(work);
    }

    /** A batch a pool worker's run held: of stand-ins only, run in the pool's passes. */
    @Override
    public void scheduleWoken(WokenBatch batch) {
        pool.scheduleWoken(batch);
    }

    /** The run of the calling pool worker; null on any other thread. */
    @Override
    public SliceRun currentRun() {
        return pool.currentRun();
    }

    @Override
    public void scheduleAfter(long delayMillis, Runnable action) {
        others.scheduleAfter(delayMillis, action);
    }

    /** The fewer of the two: the pool's, for its fairness, and the others' for their end. */
    @Override
    public int stepsPerSlice() {
        return Math.min(pool.stepsPerSlice(), others.stepsPerSlice());
    }

    @Override
    public void shutdown() {
        try {
            pool.shutdown();
        } finally {
            others.shutdown();
        }
    }
}
