package masl.runtime.entry;

import masl.runtime.Agent;
import masl.runtime.Mission;
import masl.runtime.scheduling.AgentTask;
import masl.runtime.scheduling.SliceRun;
import masl.runtime.scheduling.WokenBatch;

/**
 * Arrivals at one synchronisation barrier published together by one thread's run of slices
 * ({@link ArrivalCombiner}), in arrival order. The barrier keeps the chunk as it is, and its trip
 * lets the whole chunk go as one {@link WokenBatch}: the agents are woken by the thread that runs
 * them, preferably the one that ran them before ({@link #home}), where their state still is.
 *
 * <p>The agents are held in an array made for the chunk, not linked through the agents: an array
 * that lives one step stays in the young generation, where G1 stores references without a card
 * mark, while a link between two agents, long-lived and in different regions, costs a card mark
 * and a refinement scan per agent per step (see {@link WokenBatch#wake}).
 *
 * <p>A chunk's agents are parked at the barrier and only its trip ends their parks, so the ticket
 * each has pending when it is woken is the one of its arrival.
 */
final class ArrivalChunk implements WokenBatch {

    /**
     * How far ahead of the agent it runs a pass warms another ({@link #warm}): a chunk of a long
     * wave holds more agents than a core's cache, so warming them all before the pass would lose
     * the first before their turn; warmed a few agents ahead, the misses of the next agents overlap
     * the current one's step.
     */
    private static final int WARM_AHEAD = 8;

    /** The arrivals in arrival order, in {@code agents[0]} to {@code agents[count - 1]}; after {@link #wake}, the runnable ones. */
    private final Agent[] agents;
    final int count;
    /** The phase its agents arrived in, set when their arrivals were held. */
    int phase;
    /** The participants of the trip that let it go, set by the trip. */
    int wave;
    private final SliceRun home;
    private final Mission mission;
    /** Whether {@link #wake} warms its agents first, and a pass a few ahead ({@link ArrivalCombiner#WARM_FROM}). */
    private final boolean warm;
    /** What {@link Agent#warmUp} returned, kept so that its reads are made. */
    private int warmth;
    /** The chunk published before it, while both wait on the barrier's stack. */
    ArrivalChunk below;

    /**
     * A chunk of {@code agents[0]} to {@code agents[count - 1]}; it takes the array over. If
     * {@code warm}, its wake-up first reads each agent's state ({@link Agent#warmUp}).
     */
    ArrivalChunk(Agent[] agents, int count, SliceRun home, Mission mission, boolean warm) {
        this.agents = agents;
        this.count = count;
        this.home = home;
        this.mission = mission;
        this.warm = warm;
    }

    /** The {@code index}th arrival, before {@link #wake}. */
    Agent arrival(int index) {
        return agents[index];
    }

    private void warmAll() {
        int warmth = 0;
        for (int i = 0; i < count; i++) {
            warmth += agents[i].warmUp();
        }
        this.warmth = warmth;
    }

    @Override
    public SliceRun home() {
        return home;
    }

    @Override
    public int wave() {
        return wave;
    }

    @Override
    public int wake() {
        if (warm) {
            warmAll();
        }
        int runnable = 0;
        for (int i = 0; i < count; i++) {
            Agent agent = agents[i];
            agents[i] = null;
            if (agent.endPark(agent.pendingTicket())) {
                agents[runnable++] = agent;
            }
        }
        mission.outsideWakeUpEnded();
        return runnable;
    }

    /**
     * A pass over the chunk: wakes each agent straight into its slice, one after the other, on the
     * calling thread, so that an agent-step costs one update of the agent's scheduling state where a
     * wake-up and the start of its slice take two, and the chunk's agents are read once per step,
     * not once to wake them and again to run them. An agent that is not parked with the ticket of
     * its arrival (an invocation is being served on its behalf) is woken as {@link #wake} does.
     * The pending wake-up lasts until the last agent has been woken. Agents come to the chunk the
     * pass will publish next through their own arrivals, which the thread's run holds
     * ({@link ArrivalCombiner}).
     */
    @Override
    public int run(Slices slices) {
        int ran = 0;
        int warmth = 0;
        int ahead = warm ? Math.min(WARM_AHEAD, count) : 0;
        for (int i = 0; i < ahead; i++) {
            warmth += agents[i].warmUp();
        }
        try {
            for (int i = 0; i < count; i++) {
                if (warm && i + WARM_AHEAD < count) {
                    warmth += agents[i + WARM_AHEAD].warmUp();
                }
                Agent agent = agents[i];
                agents[i] = null;
                long ticket = agent.pendingTicket();
                if (slices.wokenSlice(agent, ticket)) {
                    ran++;
                } else if (agent.endPark(ticket)) {
                    slices.slice(agent);
                    ran++;
                }
            }
        } finally {
            mission.outsideWakeUpEnded();
        }
        this.warmth = warmth;
        return ran;
    }

    @Override
    public AgentTask runnable(int index) {
        return agents[index];
    }
}
