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
 * mission waits for that step's next request, or for the end of the step in which its program
 * finished: its stand-in is parked, and the message's arrival makes it runnable; and no stand-in has
 * a thread of its own: their slices run on the mission's pool ({@link StandInsOnAPool}). A mission of
 * a thousand deployed agents thus needs no thread per agent.
 */
@Timeout(60)
class StandInThreadsTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    /** How long the stand-ins have to let go of their threads once every step is held: ample, a failure's bound only. */
    private static final long PATIENCE_NANOS = Duration.ofSeconds(5).toNanos();
    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    private static final int AGENTS = 8;
    private static final int STEPS = 4;

    private final CountDownLatch holding = new CountDownLatch(AGENTS);
    private final CountDownLatch released = new CountDownLatch(1);
    /** The threads found waiting for a container in a stand-in's step when the patience ran out. */
    private final List<String> stillWaiting = new CopyOnWriteArrayList<>();
    /** The threads of one agent each (a thread-per-agent scheduler's) alive while the steps were held. */
    private final List<String> ownThreads = new CopyOnWriteArrayList<>();

    @Test
    void standInsWaitingForTheirContainerHoldNoThread() throws Exception {
        assertNoThreadWaitsWhileEveryStepIsHeld(2);
    }

    /** Every program finished, and the ends of their steps are slow to come: the mission waits for them, holding no thread. */
    @Test
    void standInsWaitingForTheEndOfTheirLastStepHoldNoThread() throws Exception {
        assertNoThreadWaitsWhileEveryStepIsHeld(STEPS + 1);
    }

    /** Every agent stays in its container in step {@code held} (after finishing, if beyond {@link #STEPS}) until released. */
    private void assertNoThreadWaitsWhileEveryStepIsHeld(int held) throws Exception {
        ThreadSnapshot before = ThreadSnapshot.take();
        Thread watcher = new Thread(() -> {
            try {
                holding.await();
                // Every step runs in its container: each stand-in, answered its resumption, lets go of its thread.
                long deadline = System.nanoTime() + PATIENCE_NANOS;
                List<Thread> waiting = standInThreads();
                while (!waiting.isEmpty() && System.nanoTime() < deadline) {
                    Thread.sleep(10);
                    waiting = standInThreads();
                }
                waiting.forEach(thread -> stillWaiting.add(thread.getName()));
                // Nor has any stand-in a thread of its own: the mission's pool runs their slices.
                before.startedSince().stream().map(Thread::getName)
                        .filter(name -> name.startsWith("masl-agent-")).forEach(ownThreads::add);
                released.countDown();
            } catch (InterruptedException stopped) {
                Thread.currentThread().interrupt();
            }
        }, "stand-in-threads-watcher");
        watcher.setDaemon(true);
        watcher.start();
        Set<String> all = IntStream.range(0, AGENTS).mapToObj(i -> "a" + i).collect(Collectors.toSet());
        InMemoryDeployment.Run run = InMemoryDeployment.run(() -> TestPrograms.of(MAIN, AGENTS,
                self -> new HeldStep(self, MAIN, STEPS, held, this::hold)), all,
                TIMEOUT);
        assertTrue(run.outcome().completed(), run.outcome().toString());
        assertEquals("done\n".repeat(AGENTS), run.outcome().journal());
        assertEquals(List.of(), stillWaiting, "threads waiting in a stand-in's step for its container");
        assertEquals(List.of(), ownThreads, "a thread per stand-in");
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
    private void hold(TestAgent held) {
        holding.countDown();
        try {
            Blocking.call(() -> {
                released.await();
                return null;
            });
        } catch (Exception interrupted) {
            throw new IllegalStateException(interrupted);
        }
    }
}
