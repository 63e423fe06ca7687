package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A mission open to outside invocations (the JADE bridge's): an agent busy-waiting for one is not a
 * deadlock; an invocation ends the wait.
 */
@Timeout(60)
class OutsideInvocationsTest {

    private final AtomicBoolean released = new AtomicBoolean();
    private final CountDownLatch waiting = new CountDownLatch(1);

    /**
     * {@code while (!released) {}}, where only an outside invocation sets {@code released}. Written by
     * hand: in MASL a condition that reads what such an invocation can set (an attribute, a primitive's
     * answer) makes the loop a spinning one, not a parked busy-wait.
     */
    private Mission.Builder waitingForRelease() {
        return Mission.builder().agent("a", new TestAgent(), self -> new CompactProgram(self) {
            @Override
            protected void resume(AgentContext ctx) {
                waiting.countDown();
                while (!released.get()) {
                    if (!ctx.busyWaitIteration()) {
                        return;
                    }
                }
                self.logln("released");
                ctx.finish();
            }
        });
    }

    @Test
    void aBusyWaitNobodyOutsideCanEndIsADeadlock() throws InterruptedException {
        MissionOutcome outcome = waitingForRelease().build().run(Duration.ofSeconds(30));

        assertEquals(MissionOutcome.Status.DEADLOCKED, outcome.status());
    }

    @Test
    void aBusyWaitAnOutsideInvocationMayEndIsNoDeadlock() throws InterruptedException {
        MissionOutcome outcome = waitingForRelease().openToOutsideInvocations().build()
                .run(Mission.WATCHDOG_PERIOD.multipliedBy(10));

        assertEquals(MissionOutcome.Status.TIMED_OUT, outcome.status());
    }

    @Test
    void agentsStuckAtBarriersAreADeadlockEvenOpenToOutsideInvocations() throws InterruptedException {
        Mission.Builder stuck = MissionTest.STUCK.newMission(TestAgent::new).openToOutsideInvocations();

        assertEquals(MissionOutcome.Status.DEADLOCKED, stuck.build().run(Duration.ofSeconds(30)).status());
    }

    @Test
    void anOutsideInvocationEndsTheBusyWait() throws InterruptedException {
        Mission mission = waitingForRelease().openToOutsideInvocations().build();
        Thread caller = new Thread(() -> {
            try {
                waiting.await();
                mission.submitInvocation(0, () -> released.set(true));
            } catch (InterruptedException stopped) {
                Thread.currentThread().interrupt();
            }
        });
        caller.start();

        MissionOutcome outcome = mission.run(Duration.ofSeconds(30));
        caller.join();

        assertEquals(MissionOutcome.Status.COMPLETED, outcome.status());
        assertEquals("released\n", outcome.journal());
    }
}
