package masl.runtime.entry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import masl.runtime.Agent;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.scheduling.ChangeEpoch;
import masl.runtime.scheduling.SliceRun;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Arrivals a thread's run of slices holds: they count at the barrier only once flushed, all at
 * once and in arrival order, and the flush that completes the phase trips it. Played on one thread.
 */
class ArrivalCombinerTest {

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);

    private Agent[] agents;
    private final List<TraceEvent> trace = new ArrayList<>();
    private SynchronisationBarrier barrier;
    private ArrivalCombiner combiner;

    @BeforeEach
    void missionOfThreeAgents() {
        FinishingAgents built = new FinishingAgents(MAIN, 3);
        agents = built.agents;
        barrier = built.mission.entry(MAIN).barrier;
        EntryCoordinator coordinator = new EntryCoordinator(built.mission, trace::add, System::nanoTime, new ChangeEpoch());
        combiner = new ArrivalCombiner(coordinator, built.mission, new SliceRun());
        for (int i = 0; i < agents.length; i++) {
            barrier.addParticipant();
        }
    }

    @Test
    void heldArrivalsCountOnlyOnceFlushedAndTheFlushThatCompletesThePhaseTripsIt() {
        combiner.arrive(agents[2], barrier);
        combiner.arrive(agents[0], barrier);
        combiner.arrive(agents[1], barrier);
        assertFalse(barrier.isComplete(), "held, the last arrival has not completed the phase");
        assertTrue(trace.isEmpty());

        assertTrue(combiner.flush());
        assertEquals(1, trace.size());
        TraceEvent.BarrierTripped trip = (TraceEvent.BarrierTripped) trace.get(0);
        assertEquals(new TraceEvent.BarrierTripped(trip.nanos(), "main", 3), trip);
        assertFalse(barrier.completes(0), "phase 0 tripped");
        assertFalse(combiner.flush(), "nothing left to flush");
    }

    @Test
    void aRunIsAskedToFlushTwoChunksPerThreadOfTheParticipantsOfItsLatestBarrier() {
        assertEquals(SliceRun.DEFAULT_SLICES_PER_FLUSH, combiner.slicesPerFlush(2), "nothing published yet");
        for (int i = 0; i < 997; i++) {
            barrier.addParticipant();
        }
        combiner.arrive(agents[0], barrier);
        assertEquals(SliceRun.DEFAULT_SLICES_PER_FLUSH, combiner.slicesPerFlush(2), "held, not published");
        assertTrue(combiner.flush());
        assertEquals(1_000 / (2 * 2), combiner.slicesPerFlush(2));
        assertEquals(1_000 / 2, combiner.slicesPerFlush(1));
    }

    @Test
    void aFlushPublishesTheArrivalsInTheOrderTheyWereMade() {
        combiner.arrive(agents[2], barrier);
        combiner.arrive(agents[0], barrier);
        assertTrue(combiner.flush());
        assertTrue(trace.isEmpty(), "agent 1 has not arrived");
        assertEquals(0, barrier.arrive(agents[1]));
        List<Agent> letGo = new ArrayList<>();
        List<ArrivalChunk> chunks = new ArrayList<>();
        barrier.trip(null, letGo::add, chunks::add);
        assertEquals(List.of(agents[1]), letGo);
        assertEquals(1, chunks.size());
        ArrivalChunk chunk = chunks.get(0);
        assertEquals(List.of(agents[2], agents[0]), List.of(chunk.arrival(0), chunk.arrival(1)));
        assertEquals(2, chunk.count);
    }

    @Test
    void moreArrivalsThanAFlushUsuallyHoldsArePublishedAllInTheirOrder() {
        FinishingAgents built = new FinishingAgents(MAIN, 70);
        SynchronisationBarrier big = built.mission.entry(MAIN).barrier;
        EntryCoordinator coordinator = new EntryCoordinator(built.mission, trace::add, System::nanoTime, new ChangeEpoch());
        ArrivalCombiner holding = new ArrivalCombiner(coordinator, built.mission, new SliceRun());
        List<Agent> arrived = new ArrayList<>();
        for (int i = built.agents.length - 1; i >= 0; i--) {
            big.addParticipant();
            if (i > 0) {
                holding.arrive(built.agents[i], big);
                arrived.add(built.agents[i]);
            }
        }
        assertTrue(holding.flush());
        assertEquals(0, big.arrive(built.agents[0]));
        List<ArrivalChunk> chunks = new ArrayList<>();
        big.trip(null, agent -> { }, chunks::add);
        assertEquals(1, chunks.size());
        ArrivalChunk chunk = chunks.get(0);
        assertEquals(69, chunk.count);
        List<Agent> published = new ArrayList<>();
        for (int i = 0; i < chunk.count; i++) {
            published.add(chunk.arrival(i));
        }
        assertEquals(arrived, published);
    }
}
