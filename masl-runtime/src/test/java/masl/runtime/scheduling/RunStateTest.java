package masl.runtime.scheduling;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;

/**
 * One agent's scheduling state machine, one transition at a time: which unpark ends which park, and
 * what a wake-up that comes while the agent runs or is served leaves for its slice to do.
 */
class RunStateTest {

    private final AtomicInteger counted = new AtomicInteger();
    private final RunState run = new LoneRunState(counted::incrementAndGet);

    /** A slice that started and issued the ticket of a park: the state a waiting runtime call leaves. */
    private long runningWithTicket() {
        assertTrue(run.startSlice());
        long ticket = run.issueTicket();
        assertEquals(ticket, run.pendingTicket());
        return ticket;
    }

    @Test
    void theUnparkOfThePendingTicketMakesAParkedAgentRunnableOnce() {
        long ticket = runningWithTicket();
        assertTrue(run.park(false));
        assertTrue(run.isParked());

        assertTrue(run.endPark(ticket), "the caller must schedule it");
        assertEquals(0, run.pendingTicket());
        assertFalse(run.endPark(ticket), "a repeated unpark");
        assertTrue(run.startSlice());
    }

    @Test
    void aPassEndsTheParkOfThePendingTicketStraightIntoASlice() {
        long ticket = runningWithTicket();
        assertTrue(run.park(false));

        assertFalse(run.resumeParked(ticket + 1), "another ticket");
        assertTrue(run.isParked());
        assertTrue(run.resumeParked(ticket));
        assertEquals(0, run.pendingTicket());
        assertFalse(run.isParked());
        assertFalse(run.endPark(ticket), "that park has ended");
        long next = run.issueTicket();
        assertTrue(run.park(false), "the slice runs as one its scheduler started");
        assertEquals(next, run.pendingTicket());
    }

    @Test
    void aPassLeavesAnAgentBeingServedToItsServingSlice() {
        long ticket = runningWithTicket();
        assertTrue(run.park(false));
        assertTrue(run.claimServing(() -> true));

        assertFalse(run.resumeParked(ticket));
        assertTrue(run.isServing());
        assertFalse(run.endPark(ticket), "noted for the serving slice, which schedules the program");
        assertFalse(run.park(true), "woken while served");
    }

    @Test
    void anAgentAwayWhileItsStepRunsElsewhereIsWokenAsParkedButNeitherServedNorIdle() {
        long ticket = runningWithTicket();
        assertTrue(run.parkAway());

        assertFalse(run.claimServing(() -> true), "its step runs: it serves at its own boundary");
        assertFalse(run.isIdle(true, () -> true), "the deadlock watchdog counts it running");
        assertFalse(run.isParked());
        assertFalse(run.resumeParked(ticket), "no barrier's pass lets it go");
        assertTrue(run.endPark(ticket), "the caller must schedule it");
        assertEquals(0, run.pendingTicket());
        assertTrue(run.startSlice());
        long next = run.issueTicket();
        assertFalse(run.endPark(next), "woken before its slice ended");
        assertFalse(run.parkAway(), "the slice reschedules it");
    }

    @Test
    void aStaleTicketEndsNoLaterPark() {
        long first = runningWithTicket();
        assertTrue(run.park(false));
        assertTrue(run.endPark(first));
        assertTrue(run.startSlice());
        long second = run.issueTicket();
        assertTrue(run.park(false));

        assertFalse(run.endPark(first));
        assertTrue(run.isParked());
        assertEquals(second, run.pendingTicket());
        assertTrue(run.endPark(second));
    }

    @Test
    void anUnparkWhileTheSliceRunsIsLeftToTheSliceWhichReschedules() {
        long ticket = runningWithTicket();
        assertFalse(run.endPark(ticket), "the slice is still running");
        assertFalse(run.park(false), "the park ended before the slice did");
        assertFalse(run.isParked());

        run.reschedule();
        assertTrue(run.startSlice());
    }

    @Test
    void aParkTakenBackIsEndedByNobody() {
        long ticket = runningWithTicket();
        assertTrue(run.takeBack(ticket));
        assertEquals(0, run.pendingTicket());
        assertFalse(run.endPark(ticket));
        assertFalse(run.takeBack(ticket));
    }

    @Test
    void aServingSliceKeepsThePendingTicketAndAnUnparkMeanwhileReschedulesTheProgram() {
        long ticket = runningWithTicket();
        assertTrue(run.park(false));
        assertTrue(run.claimServing(() -> true));
        assertTrue(run.isServing());
        assertEquals(ticket, run.pendingTicket(), "the agent still waits for its park to end");
        assertEquals(1, counted.get(), "leaving PARKED is counted for the deadlock watchdog");

        assertFalse(run.endPark(ticket), "the serving slice notes it");
        assertTrue(run.isServing());
        assertFalse(run.park(true));
        run.reschedule();
        assertTrue(run.startSlice());
    }

    @Test
    void aServingSliceReturnsTheAgentToItsPark() {
        long ticket = runningWithTicket();
        assertTrue(run.park(false));
        assertTrue(run.claimServing(() -> true));
        assertTrue(run.park(true));

        assertTrue(run.isParked());
        assertTrue(run.endPark(ticket));
    }

    @Test
    void onlyABlockedOrFinishedAgentIsClaimedForServing() {
        runningWithTicket();
        assertFalse(run.claimServing(() -> true), "a running agent serves at its own boundary");
        assertTrue(run.park(false));
        assertFalse(run.claimServing(() -> false), "nothing to serve");
        assertTrue(run.isParked());

        run.done();
        assertTrue(run.claimServing(() -> true));
        run.done();
        assertTrue(run.isDone());
    }

    @Test
    void aSliceStartsOnlyFromScheduled() {
        long ticket = runningWithTicket();
        assertFalse(run.startSlice(), "already running");
        assertTrue(run.park(false));
        assertFalse(run.startSlice(), "parked");
        assertTrue(run.endPark(ticket));
        assertTrue(run.startSlice());
    }

    /** Two threads unpark the same ticket at once, many times: exactly one makes the agent runnable. */
    @Test
    void ofTwoConcurrentUnparksOfOneTicketExactlyOneWins() throws Exception {
        CyclicBarrier together = new CyclicBarrier(2);
        for (int round = 0; round < 2_000; round++) {
            long ticket = runningWithTicket();
            assertTrue(run.park(false));
            AtomicInteger winners = new AtomicInteger();
            Thread other = new Thread(() -> unparkTogether(together, ticket, winners));
            other.start();
            unparkTogether(together, ticket, winners);
            other.join();
            assertEquals(1, winners.get(), "round " + round);
            assertEquals(0, run.pendingTicket());
        }
    }

    private void unparkTogether(CyclicBarrier together, long ticket, AtomicInteger winners) {
        try {
            together.await();
        } catch (Exception e) {
            throw new AssertionError(e);
        }
        if (run.endPark(ticket)) {
            winners.incrementAndGet();
        }
    }
}
