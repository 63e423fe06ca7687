package masl.runtime.scheduling;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The deadlock watchdog's counts are kept by each thread apart, yet a look reads them as one: a
 * wake-up begun on one thread (a barrier's trip) and ended on another (the worker that runs the
 * chunk it let go) is pending in between and not after, and a count on any thread moves the look.
 */
class WakeUpsTest {

    @Test
    void aWakeUpBegunOnOneThreadAndEndedOnAnotherIsPendingUntilItEnds() throws Exception {
        WakeUps wakeUps = new WakeUps();
        long quiet = wakeUps.look();
        assertTrue(WakeUps.nonePending(quiet));

        onAnotherThread(wakeUps::pendingStarted);
        long pending = wakeUps.look();
        assertFalse(WakeUps.nonePending(pending));

        onAnotherThread(wakeUps::pendingEnded);
        long ended = wakeUps.look();
        assertTrue(WakeUps.nonePending(ended));
        assertNotEquals(quiet, ended, "the wake-up was counted when it began");
    }

    @Test
    void aCountOnAnyThreadMovesTheLook() throws Exception {
        WakeUps wakeUps = new WakeUps();
        long before = wakeUps.look();
        onAnotherThread(wakeUps::counted);
        long afterOne = wakeUps.look();
        assertNotEquals(before, afterOne);
        wakeUps.counted();
        long afterTwo = wakeUps.look();
        assertNotEquals(afterOne, afterTwo);
        assertTrue(WakeUps.nonePending(afterTwo));
    }

    /** Runs {@code action} on a new thread, and waits for it: each call is a thread of its own. */
    private static void onAnotherThread(Runnable action) throws InterruptedException {
        Thread thread = new Thread(action);
        thread.start();
        thread.join();
    }
}
