package masl.runtime.scheduling;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A wave made runnable at once ({@link Scheduler#scheduleAll}) as one item of a
 * {@link PoolScheduler}'s run queue: the runners claim its agents a chunk at a time, one atomic
 * add per chunk instead of a queue node and a poll per agent, and it stays at the head of the queue
 * until its last chunk is claimed, so what is queued after it still waits behind all of it.
 */
final class RunBatch {

    private final AgentTask[] agents;
    private final AtomicInteger claimed = new AtomicInteger();

    RunBatch(List<? extends AgentTask> agents) {
        this.agents = agents.toArray(new AgentTask[0]);
    }

    /** Claims the next chunk of at most {@code chunk} agents: its first index, or {@link #size} if none is left. */
    int claim(int chunk) {
        return Math.min(claimed.getAndAdd(chunk), agents.length);
    }

    int size() {
        return agents.length;
    }

    AgentTask get(int index) {
        return agents[index];
    }
}
