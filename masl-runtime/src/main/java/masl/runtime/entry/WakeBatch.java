package masl.runtime.entry;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import masl.runtime.Agent;
import masl.runtime.Mission;
import masl.runtime.scheduling.Scheduler;

/**
 * The parked agents one {@link EntryCoordinator} operation lets go (a barrier trip, a release, an
 * exit barrier), with the tickets of their parks: collected under the coordinator's lock, woken
 * together after it, and handed to the scheduler in one {@link Scheduler#scheduleAll} call, so a
 * trip makes its whole wave runnable in one pass. Reused from operation to operation: waking a
 * wave allocates nothing.
 */
final class WakeBatch {

    private Agent[] agents = new Agent[16];
    private long[] tickets = new long[16];
    private int size;
    private final List<Agent> runnable = new ArrayList<>();
    /** Chunks of arrivals let go, woken by whoever runs them (pending wake-ups, begun already). */
    private final List<ArrivalChunk> chunks = new ArrayList<>();

    /** Adds a parked agent with the ticket of its pending park; the running agent (no pending park) needs no wake-up. */
    void addParked(Agent agent) {
        long ticket = agent.pendingTicket();
        if (ticket != 0) {
            add(agent, ticket);
        }
    }

    private void add(Agent agent, long ticket) {
        if (size == agents.length) {
            agents = Arrays.copyOf(agents, size * 2);
            tickets = Arrays.copyOf(tickets, size * 2);
        }
        agents[size] = agent;
        tickets[size] = ticket;
        size++;
    }

    /** Adds a chunk let go whole, whose pending wake-up its letting go has begun. */
    void addChunk(ArrivalChunk chunk) {
        chunks.add(chunk);
    }

    boolean isEmpty() {
        return size == 0 && chunks.isEmpty();
    }

    /** Unparks every agent of the batch (stale tickets are ignored, as by {@link Agent#unpark}) and empties it. */
    void wakeAll(Mission mission) {
        // Counted before any agent leaves PARKED, for the deadlock watchdog.
        mission.countSchedule();
        for (int i = 0; i < size; i++) {
            Agent agent = agents[i];
            if (agent.endPark(tickets[i])) {
                runnable.add(agent);
            }
            agents[i] = null;
        }
        size = 0;
        if (!runnable.isEmpty()) {
            mission.scheduler().scheduleAll(runnable);
            runnable.clear();
        }
        for (ArrivalChunk chunk : chunks) {
            mission.scheduler().scheduleWoken(chunk);
        }
        chunks.clear();
    }
}
