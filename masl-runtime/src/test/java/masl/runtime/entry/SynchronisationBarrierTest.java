package masl.runtime.entry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import masl.runtime.Agent;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.Mode;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * The barrier's state machine, one interleaving at a time: each test plays, on one thread, an
 * order of lock-free arrivals and membership changes that threads can produce, including those
 * that only a preemption between an arrival's count and its taking the coordinator's lock makes
 * possible, which a running mission hits too rarely to test them.
 */
class SynchronisationBarrierTest {

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);

    private SynchronisationBarrier barrier;
    private Agent[] agents;
    private Mission mission;
    private final List<Agent> letGo = new ArrayList<>();
    private final List<ArrivalChunk> chunks = new ArrayList<>();

    @BeforeEach
    void missionOfFourAgents() {
        FinishingAgents built = new FinishingAgents(MAIN, 4);
        agents = built.agents;
        mission = built.mission;
        barrier = mission.entry(MAIN).barrier;
    }

    @Test
    void onlyTheLastArrivalCompletesAndTheTripLetsTheOthersGoInArrivalOrder() {
        participants(3);
        assertEquals(-1, barrier.arrive(agents[1]));
        assertEquals(-1, barrier.arrive(agents[0]));
        assertEquals(0, barrier.arrive(agents[2]));
        assertTrue(barrier.completes(0));
        assertEquals(3, barrier.trip(agents[2], letGo::add, chunks::add));
        assertEquals(List.of(agents[1], agents[0]), letGo);
        assertFalse(barrier.completes(0), "phase 0 trips once");

        letGo.clear();
        assertEquals(-1, barrier.arrive(agents[2]));
        assertEquals(-1, barrier.arrive(agents[1]));
        assertEquals(1, barrier.arrive(agents[0]));
        assertEquals(3, barrier.trip(agents[0], letGo::add, chunks::add));
        assertEquals(List.of(agents[2], agents[1]), letGo);
    }

    @Test
    void aParticipantJoiningBeforeTheCompletingArrivalTripsIsWaitedFor() {
        participants(2);
        barrier.arrive(agents[0]);
        assertEquals(0, barrier.arrive(agents[1]));
        barrier.addParticipant();
        assertFalse(barrier.completes(0), "the completing arrival stays parked: agent 2 joined first");
        assertEquals(0, barrier.arrive(agents[2]));
        assertTrue(barrier.completes(0));
        assertEquals(3, barrier.trip(agents[2], letGo::add, chunks::add));
        assertEquals(List.of(agents[0], agents[1]), letGo);
    }

    @Test
    void aChangeThatCompletesThePhaseFirstTripsItForTheCompletingArrival() {
        participants(2);
        barrier.arrive(agents[0]);
        assertEquals(0, barrier.arrive(agents[1]));
        barrier.addParticipant();
        barrier.removeParticipant(agents[2]);
        assertTrue(barrier.isComplete());
        assertEquals(2, barrier.trip(null, letGo::add, chunks::add));
        assertEquals(List.of(agents[0], agents[1]), letGo, "the completing arrival is woken too");
        assertFalse(barrier.completes(0), "and finds its phase tripped");
    }

    @Test
    void aLeaverWhileTheOthersWaitCompletesThePhase() {
        participants(3);
        barrier.arrive(agents[0]);
        barrier.arrive(agents[1]);
        assertFalse(barrier.isComplete());
        barrier.removeParticipant(agents[2]);
        assertTrue(barrier.isComplete());
        assertEquals(2, barrier.trip(null, letGo::add, chunks::add));
        assertEquals(List.of(agents[0], agents[1]), letGo);
    }

    @Test
    void aLeaverAfterATripIsNoLongerCountedAsArrived() {
        participants(2);
        barrier.arrive(agents[0]);
        barrier.arrive(agents[1]);
        barrier.trip(agents[1], letGo::add, chunks::add);
        barrier.removeParticipant(agents[0]);
        assertFalse(barrier.isComplete(), "agent 1 has not arrived in phase 1");
        assertEquals(1, barrier.arrive(agents[1]));
        assertEquals(1, barrier.trip(agents[1], letGo::add, chunks::add));
    }

    @Test
    void anAgentThatDiesAfterArrivingKeepsItsArrivalCountedAndIsNotCountedInTheTrip() {
        participants(3);
        barrier.arrive(agents[0]);
        barrier.removeParticipant(agents[0]);
        assertEquals(-1, barrier.arrive(agents[1]));
        assertEquals(0, barrier.arrive(agents[2]));
        assertEquals(2, barrier.trip(agents[2], letGo::add, chunks::add));
    }

    @Test
    void aDomainWithoutParticipantsNeverTrips() {
        participants(1);
        barrier.removeParticipant(agents[0]);
        assertFalse(barrier.isComplete());
        assertThrows(IllegalStateException.class, () -> barrier.trip(null, letGo::add, chunks::add));
    }

    @Test
    void anArrivalOfAnAgentThatDoesNotTakePartIsARuntimeBug() {
        participants(1);
        barrier.arrive(agents[0]);
        assertThrows(IllegalStateException.class, () -> barrier.arrive(agents[1]));
    }

    @Test
    void arrivalsPublishedTogetherCountAsManyAndTheTripLetsTheirChunkGoWhole() {
        participants(4);
        assertEquals(-1, barrier.arrive(agents[3]));
        ArrivalChunk first = chunk(agents[0], agents[2]);
        assertEquals(-1, barrier.arriveAll(first));
        assertFalse(barrier.isComplete(), "agent 1 has not arrived");
        ArrivalChunk second = chunk(agents[1]);
        assertEquals(0, barrier.arriveAll(second));
        assertEquals(4, barrier.trip(null, letGo::add, chunks::add));
        assertEquals(List.of(agents[3]), letGo);
        assertEquals(List.of(first, second), chunks, "in the order they were published");
        assertEquals(agents[2], first.arrival(1), "the chunk keeps its arrival order");
        assertFalse(barrier.completes(0), "phase 0 trips once");
    }

    @Test
    void anAgentThatDiesAfterItsArrivalWasPublishedWithOthersKeepsItCounted() {
        participants(3);
        barrier.arriveAll(chunk(agents[0], agents[1]));
        barrier.removeParticipant(agents[1]);
        assertEquals(0, barrier.arrive(agents[2]));
        assertEquals(2, barrier.trip(agents[2], letGo::add, chunks::add));
        assertEquals(1, chunks.size());
    }

    @Test
    void morePublishedArrivalsThanUnarrivedParticipantsIsARuntimeBug() {
        participants(2);
        barrier.arrive(agents[0]);
        assertThrows(IllegalStateException.class, () -> barrier.arriveAll(chunk(agents[1], agents[2])));
    }

    /** A chunk of agents given in arrival order, each marked as arrived in the current phase, as an ArrivalCombiner makes it. */
    private ArrivalChunk chunk(Agent... inArrivalOrder) {
        ArrivalChunk chunk = new ArrivalChunk(inArrivalOrder.clone(), inArrivalOrder.length, null, mission, true);
        chunk.phase = barrier.phase();
        for (Agent agent : inArrivalOrder) {
            barrier.markArrival(agent, chunk.phase);
        }
        return chunk;
    }

    private void participants(int count) {
        for (int i = 0; i < count; i++) {
            barrier.addParticipant();
        }
    }
}
