package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import masl.runtime.scheduling.Blocking;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Waiting without holding a thread: sleep, busy-wait loops (MASL §5, §12), blocking primitives. */
@Timeout(120)
class SuspensionTest {

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   shared int flag = 0;
     *   shared int in = 0;
     *   if (.getProxyID() == 0) { while (in == 0) {} .sleep(30); flag = 1; }
     *   else { in = 1; while (flag == 0) {} .logln("woke"); }
     * }
     * </pre>
     *
     * Written by hand: the test counts how often the busy-wait's test is evaluated, which MASL
     * cannot observe: a primitive call in the test would make the loop a spinning one, not parked.
     *
     * Agent 0 waits for agent 1 to be in the block before it sleeps: without that, an agent 1
     * whose first slice came late (a starved thread) entered a new wave of {@code main} after agent
     * 0 had left it, with a fresh {@code flag}, and waited for ever: a real deadlock, reported so.
     */
    static final class SleepAndBusyWait extends CompactProgram {
        static final long SLEEP_MS = 30;
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final SharedDeclaration<Integer> FLAG = MAIN.declareShared("flag", 0);
        static final SharedDeclaration<Integer> IN = MAIN.declareShared("in", 0);

        private final AtomicLong sleptNanos;
        private final AtomicInteger iterations;
        private long sleepStart;

        SleepAndBusyWait(TestAgent self, AtomicLong sleptNanos, AtomicInteger iterations) {
            super(self);
            this.sleptNanos = sleptNanos;
            this.iterations = iterations;
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 7)) return; continue;
                    case 1:
                        ctx.shared(FLAG).initialise(() -> 0);
                        ctx.shared(IN).initialise(() -> 0);
                        if (self.getProxyID() != 0) {
                            ctx.shared(IN).set(1);
                            pc = 4;
                            continue;
                        }
                        pc = 9;
                        continue;
                    case 9:
                        if (!busyWait(ctx, ctx.shared(IN).get() == 0, 10)) return;
                        continue;
                    case 10:
                        sleepStart = System.nanoTime();
                        pc = 2;
                        if (!ctx.sleep(SLEEP_MS)) return;
                    case 2:
                        sleptNanos.set(System.nanoTime() - sleepStart);
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3: ctx.shared(FLAG).set(1); if (!step(ctx, 6)) return; continue;
                    case 4:
                        iterations.incrementAndGet();
                        if (!busyWait(ctx, ctx.shared(FLAG).get() == 0, 5)) return;
                        continue;
                    case 5: self.logln("woke"); if (!step(ctx, 6)) return; continue;
                    case 6: if (!leave(ctx, MAIN, 7)) return; continue;
                    case 7: if (!endOf(ctx, MAIN.sequence(), 8)) return; continue;
                    case 8: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void sleepSuspendsAndABusyWaitParksUntilAChangeItCanSee(Driver driver) {
        for (int run = 0; run < 10; run++) {
            AtomicLong slept = new AtomicLong();
            AtomicInteger iterations = new AtomicInteger();
            String journal = Missions.run(driver, SleepAndBusyWait.MAIN, 2,
                    self -> new SleepAndBusyWait(self, slept, iterations)).journal();
            assertEquals("woke\n", journal);
            if (driver != Driver.SEEDED) {
                // Real time: the sleep lasts at least as asked (virtual time takes none).
                assertTrue(slept.get() >= TimeUnit.MILLISECONDS.toNanos(SleepAndBusyWait.SLEEP_MS), () -> "slept " + slept);
            }
            // A spinning loop iterates thousands of times during the sleep. A parked one iterates
            // at most three times per change the mission makes (it sees the change, finds nothing
            // new, and may be woken once more by the same change), and this mission makes six:
            // two arrivals at main, two writes, two departures.
            assertTrue(iterations.get() <= 2 + 3 * 6, () -> iterations + " iterations");
        }
    }

    /**
     * Agent 0's primitive ({@code nop}) blocks its thread until agent 1's ({@code log}) opens a
     * latch: with one worker, only a pool that adds a worker while a primitive blocks gets there.
     * (The seeded scheduler runs everything on one thread by design, so it cannot run this program.)
     */
    private static final MaslProgram BLOCKING_PRIMITIVE = MaslProgram.of("blocking.masl", MaslProgram.header(2) + """
            asynchronous entry main (true) {
              if (.getProxyID() == 0) .nop(); else .log("open");
            }
            """);

    /** Blocks in {@code nop} until {@code log} opens the latch. */
    private static final class Latched extends TestAgent {
        private final CountDownLatch latch;
        private final AtomicBoolean opened;

        Latched(CountDownLatch latch, AtomicBoolean opened) {
            this.latch = latch;
            this.opened = opened;
        }

        @Override
        public void nop() {
            try {
                opened.set(Blocking.call(() -> latch.await(30, TimeUnit.SECONDS)));
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
        }

        @Override
        public void log(String message) {
            latch.countDown();
        }
    }

    @ParameterizedTest
    @EnumSource(value = Driver.class, names = {"POOL", "SINGLE_WORKER", "THREADS"})
    void aPrimitiveThatBlocksItsThreadDoesNotStallTheOtherAgents(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            CountDownLatch latch = new CountDownLatch(1);
            AtomicBoolean opened = new AtomicBoolean();
            BLOCKING_PRIMITIVE.run(driver.newScheduler(), Trace.NONE, () -> new Latched(latch, opened));
            assertTrue(opened.get());
        }
    }
}
