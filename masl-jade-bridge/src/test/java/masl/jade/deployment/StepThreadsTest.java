package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Arrays;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.jade.TestPrograms;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.scheduling.Blocking;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A deployed agent whose step waits at a barrier holds no thread in its container: its program
 * returned from the boundary, and the mission's wake-up starts its next step on the container's pool.
 * A container of a thousand agents in lock-step thus needs a few threads, not a thousand.
 */
@Timeout(60)
class StepThreadsTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    private static final int AGENTS = 8;
    private static final int STEPS = 4;
    /** The step in which agent 0 keeps the barrier from tripping until the others have let go of their threads. */
    private static final int HELD = 2;

    /** The thread on which each agent but 0 ran its step {@link #HELD}, by proxy id. */
    private static final Map<Integer, Thread> RAN_ON = new ConcurrentHashMap<>();
    private static final CountDownLatch ARRIVING = new CountDownLatch(AGENTS - 1);
    private static final CountDownLatch RELEASED = new CountDownLatch(1);

    @Test
    void agentsWaitingAtTheBarrierHoldNoThreadOfTheirContainer() throws Exception {
        Thread watcher = new Thread(() -> {
            try {
                ARRIVING.await();
                // Each of the others reaches the barrier: the thread of its step comes out of its program.
                while (RAN_ON.values().stream().anyMatch(StepThreadsTest::inAContextCall)) {
                    Thread.sleep(10);
                }
                RELEASED.countDown();
            } catch (InterruptedException stopped) {
                Thread.currentThread().interrupt();
            }
        }, "step-threads-watcher");
        watcher.setDaemon(true);
        watcher.start();
        Set<String> all = IntStream.range(0, AGENTS).mapToObj(i -> "a" + i).collect(Collectors.toSet());
        InMemoryDeployment.Run run = InMemoryDeployment.run(() -> TestPrograms.of(MAIN, AGENTS,
                self -> new HeldStep(self, MAIN, STEPS, HELD, StepThreadsTest::hold)), all,
                TIMEOUT);
        assertTrue(run.outcome().completed(), run.outcome().toString());
        assertEquals("done\n".repeat(AGENTS), run.outcome().journal());
        assertEquals(AGENTS - 1, RAN_ON.size());
    }

    /** Whether {@code thread} waits in, or runs, a call of a deployed program to its mission. */
    private static boolean inAContextCall(Thread thread) {
        return Arrays.stream(thread.getStackTrace())
                .anyMatch(frame -> frame.getClassName().equals(RemoteContext.class.getName()));
    }

    /** Agent 0 stays in its step until released; the others note the thread their step ran on. */
    private static void hold(TestAgent self) {
        int id = self.getProxyID();
        if (id != 0) {
            RAN_ON.put(id, Thread.currentThread());
            ARRIVING.countDown();
            return;
        }
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
