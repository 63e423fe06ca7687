package masl.runtime.event;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;
import masl.runtime.EntryDefinition;
import masl.runtime.Event;
import masl.runtime.Mode;
import masl.runtime.testing.Missions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The per-agent event queue: many emitters at once, one taker, nothing lost, each emitter's order kept. */
@Timeout(120)
class EventQueueTest {

    private static final Event PING = EntryDefinition.main("main", Mode.ASYNCHRONOUS).declareSharedEvent("ping");

    @Test
    void takeAllReturnsEverythingOfferedOldestFirstAndEmptiesTheQueue() {
        EventQueue queue = new EventQueue();
        assertTrue(queue.isEmpty());
        for (int i = 0; i < 3; i++) {
            queue.offer(new EventOccurrence(PING, String.valueOf(i), 0));
        }
        assertEquals(List.of("0", "1", "2"), queue.takeAll().stream().map(EventOccurrence::message).toList());
        assertTrue(queue.isEmpty());
        assertEquals(List.of(), queue.takeAll());
    }

    @Test
    void concurrentEmittersWhileTheReceiverTakesLoseNothingAndKeepEachEmittersOrder() throws InterruptedException {
        int emitters = 8;
        int each = 20_000;
        for (int run = 0; run < Missions.REPETITIONS / 5; run++) {
            EventQueue queue = new EventQueue();
            CountDownLatch start = new CountDownLatch(1);
            CountDownLatch finished = new CountDownLatch(emitters);
            AtomicInteger failures = new AtomicInteger();
            List<Thread> threads = new ArrayList<>();
            for (int e = 0; e < emitters; e++) {
                int emitter = e;
                threads.add(new Thread(() -> {
                    try {
                        start.await();
                        for (int i = 0; i < each; i++) {
                            queue.offer(new EventOccurrence(PING, String.valueOf(i), emitter));
                        }
                    } catch (InterruptedException interrupted) {
                        failures.incrementAndGet();
                    } finally {
                        finished.countDown();
                    }
                }));
            }
            threads.forEach(Thread::start);
            start.countDown();
            // The receiver takes batches while the emitters push, then what is left once they are done.
            int[] next = new int[emitters];
            int taken = 0;
            while (finished.getCount() > 0 || !queue.isEmpty()) {
                for (EventOccurrence occurrence : queue.takeAll()) {
                    assertEquals(next[occurrence.emitter()]++, Integer.parseInt(occurrence.message()),
                            "order of emitter " + occurrence.emitter());
                    taken++;
                }
            }
            for (Thread thread : threads) {
                thread.join();
            }
            assertEquals(0, failures.get());
            assertEquals(emitters * each, taken);
            for (int e = 0; e < emitters; e++) {
                assertEquals(each, next[e]);
            }
        }
    }
}
