package masl.runtime.entry;

import java.util.List;
import masl.runtime.Agent;
import masl.runtime.Mission;
import masl.runtime.scheduling.AgentTask;
import masl.runtime.scheduling.SliceRun;
import masl.runtime.scheduling.WokenBatch;

/**
 * Arrivals at one synchronisation barrier published together by one thread's run of slices
 * ({@link ArrivalCombiner}), in arrival order, linked by {@link Agent#nextArrival} from
 * {@link #first} on. The barrier keeps the chunk as it is, and its trip lets the whole chunk go as
 * one {@link WokenBatch}: the agents are woken by the thread that runs them, preferably the one
 * that ran them before ({@link #home}), where their state still is.
 *
 * <p>A chunk's agents are parked at the barrier and only its trip ends their parks, so the ticket
 * each has pending when it is woken is the one of its arrival.
 */
final class ArrivalChunk implements WokenBatch {

    /** The earliest arrival; the latest links to null. */
    final Agent first;
    final int count;
    /** The phase its agents arrived in, set when the barrier counts them. */
    int phase;
    private final SliceRun home;
    private final Mission mission;
    /** The chunk published before it, while both wait on the barrier's stack. */
    ArrivalChunk below;

    ArrivalChunk(Agent first, int count, SliceRun home, Mission mission) {
        this.first = first;
        this.count = count;
        this.home = home;
        this.mission = mission;
    }

    @Override
    public SliceRun home() {
        return home;
    }

    @Override
    public void wake(List<AgentTask> runnable) {
        Agent agent = first;
        while (agent != null) {
            // Read first: once woken, the agent may arrive again, on another thread.
            Agent following = agent.nextArrival;
            agent.nextArrival = null;
            if (agent.endPark(agent.pendingTicket()) && agent.leavePark()) {
                runnable.add(agent);
            }
            agent = following;
        }
        mission.outsideWakeUpEnded();
    }
}
