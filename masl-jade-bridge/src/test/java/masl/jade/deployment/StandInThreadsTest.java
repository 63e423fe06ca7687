package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.jade.TestPrograms;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.scheduling.Blocking;
import masl.runtime.testing.TestAgent;
import masl.testing.jade.ThreadSnapshot;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A deployed agent whose step runs in its container holds no thread of its mission while the
 * mission waits for that step's next request: its stand-in is parked, and the request's arrival
 * makes it runnable; and no stand-in has a thread of its own: their slices run on the mission's pool
 * ({@link StandInsOnAPool}). A mission of a thousand deployed agents thus needs no thread per agent.
 */
@Timeout(60)
class StandInThreadsTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    /** How long the stand-ins have to let go of their threads once every step is held: ample, a failure's bound only. */
    private static final long PATIENCE_NANOS = Duration.ofSeconds(5).toNanos();
    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    private static final int AGENTS = 8;
    private static final int STEPS = 4;
    /** The step in which every agent stays in its container until released, its stand-in waiting. */
    private static final int HELD = 2;

    private static final CountDownLatch HOLDING = new CountDownLatch(AGENTS);
    private static final CountDownLatch RELEASED = new CountDownLatch(1);
    /** The threads found waiting for a container in a stand-in's step when the patience ran out. */
    private static final List<String> STILL_WAITING = new CopyOnWriteArrayList<>();
    /** The threads of one agent each (a thread-per-agent scheduler's) alive while the steps were held. */
    private static final List<String> OWN_THREADS = new CopyOnWriteArrayList<>();

    @Test
    void standInsWaitingForTheirContainerHoldNoThread() throws Exception {
        ThreadSnapshot before = ThreadSnapshot.take();
        Thread watcher = new Thread(() -> {
            try {
                HOLDING.await();
                // Every step runs in its container: each stand-in, answered its resumption, lets go of its thread.
                long deadline = System.nanoTime() + PATIENCE_NANOS;
                List<Thread> waiting = standInThreads();
                while (!waiting.isEmpty() && System.nanoTime() < deadline) {
                    Thread.sleep(10);
                    waiting = standInThreads();
                }
                waiting.forEach(thread -> STILL_WAITING.add(thread.getName()));
                // Nor has any stand-in a thread of its own: the mission's pool runs their slices.
                before.startedSince().stream().map(Thread::getName)
                        .filter(name -> name.startsWith("masl-agent-")).forEach(OWN_THREADS::add);
                RELEASED.countDown();
            } catch (InterruptedException stopped) {
                Thread.currentThread().interrupt();
            }
        }, "stand-in-threads-watcher");
        watcher.setDaemon(true);
        watcher.start();
        Set<String> all = IntStream.range(0, AGENTS).mapToObj(i -> "a" + i).collect(Collectors.toSet());
        InMemoryDeployment.Run run = InMemoryDeployment.run(() -> TestPrograms.of(MAIN, AGENTS,
                self -> new HeldStep(self, MAIN, STEPS, HELD, StandInThreadsTest::hold)), all,
                TIMEOUT);
        assertTrue(run.outcome().completed(), run.outcome().toString());
        assertEquals("done\n".repeat(AGENTS), run.outcome().journal());
        assertEquals(List.of(), STILL_WAITING, "threads waiting in a stand-in's step for its container");
        assertEquals(List.of(), OWN_THREADS, "a thread per stand-in");
    }

    /** The live threads in a stand-in's step. */
    private static List<Thread> standInThreads() {
        return Thread.getAllStackTraces().entrySet().stream()
                .filter(thread -> Arrays.stream(thread.getValue())
                        .anyMatch(frame -> frame.getClassName().equals(StandIn.class.getName())))
                .map(Map.Entry::getKey)
                .toList();
    }

    /** Every agent stays in its step until released. */
    private static void hold(TestAgent held) {
        HOLDING.countDown();
        try {
            Blocking.call(() -> {
                RELEASED.await();
                return null;
            });
        } catch (Exception interrupted) {
            throw new IllegalStateException(interrupted);
        }
    }
}
