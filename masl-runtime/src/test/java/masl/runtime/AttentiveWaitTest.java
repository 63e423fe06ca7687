package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.descriptor.AgentType;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.TestTypes;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** {@code wait(state)} and {@code wait(state, ms)} (MASL §11). */
@Timeout(120)
class AttentiveWaitTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final SharedDeclaration<Integer> ASKED = MAIN.declareShared("asked", 0);
    static final EntryDefinition GROUP = MAIN.child("group", Mode.ASYNCHRONOUS);

    /**
     * The server (agent 0) waits in state {@code onlyLog}, which lets only its group invoke
     * {@code log}. Agent 2, outside the group, asks for {@code getProxyID} first; then agent 1, in the
     * group, invokes {@code log}.
     * <pre>
     * asynchronous entry main (true) {
     *   shared int asked = 0;
     *   asynchronous entry group (me &lt;= 1) {
     *     if (me == 0) { wait("onlyLog", 2000); .logln("after wait"); }
     *     else { while (asked == 0) {} a0.log("log from 1\n"); }
     *   }
     *   if (me == 2) { id = a0.getProxyID(); asked = 1; .logln("got " + id); }
     * }
     * </pre>
     */
    static final class OnlyLog extends CompactProgram {
        private final AtomicReferenceArray<TestAgent> population;
        private CompletableFuture<Integer> asking;
        private CompletableFuture<Object> logging;

        OnlyLog(TestAgent self, AtomicReferenceArray<TestAgent> population) {
            super(self);
            this.population = population;
            population.set(self.getProxyID(), self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            TestAgent server = population.get(0);
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 13)) return; continue;
                    case 1: if (!arrive(ctx, GROUP, me <= 1, 2, 8)) return; continue;
                    case 2:
                        if (me != 0) {
                            pc = 5;
                            continue;
                        }
                        pc = 3;
                        if (!ctx.waitFor("onlyLog", 2000)) return;
                    case 3: if (!step(ctx, 4)) return; continue;
                    case 4: self.logln("after wait"); if (!step(ctx, 7)) return; continue;
                    case 5: if (!busyWait(ctx, ctx.shared(ASKED).get() == 0, 6)) return; continue;
                    case 6:
                        logging = ctx.invoke(server, "log", null, () -> {
                            server.log("log from 1\n");
                            return null;
                        });
                        pc = 16;
                        if (!ctx.await(logging)) return;
                    case 16: if (!step(ctx, 7)) return; continue;
                    case 7: if (!leave(ctx, GROUP, 8)) return; continue;
                    case 8: if (!endOf(ctx, GROUP.sequence(), 9)) return; continue;
                    case 9:
                        if (me != 2) {
                            pc = 12;
                            continue;
                        }
                        asking = ctx.invoke(server, "getProxyID", -1, () -> {
                            server.log("proxy served\n");
                            return server.getProxyID();
                        });
                        ctx.shared(ASKED).set(1);
                        pc = 10;
                        if (!ctx.await(asking)) return;
                    case 10: self.logln("got " + asking.join()); if (!step(ctx, 12)) return; continue;
                    case 12: if (!leave(ctx, MAIN, 13)) return; continue;
                    case 13: if (!endOf(ctx, MAIN.sequence(), 14)) return; continue;
                    case 14: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aWaitServesTheAllowedInvocationAndLeavesTheOthersQueuedUntilAfter(Driver driver) {
        AgentType type = TestTypes.testAgent();
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(3);
            String journal = Missions.run(driver.newScheduler(), MAIN, 3, type,
                    self -> new OnlyLog(self, population), Trace.NONE).journal();
            assertTrue(journal.startsWith("log from 1\nproxy served\n"), journal);
            assertEquals(List.of("after wait", "got 0", "log from 1", "proxy served"),
                    journal.lines().sorted().toList(), journal);
        }
    }

    /**
     * Agent 0 waits in state {@code nothing} for 300 ms, reading the mission clock before and after;
     * agent 1 invokes its {@code getProxyID} meanwhile, which runs only after the wait.
     */
    static final class Nothing extends CompactProgram {
        private final AtomicReferenceArray<TestAgent> population;
        private final Scheduler clock;
        private final AtomicLongArray times;
        private CompletableFuture<Integer> asking;

        Nothing(TestAgent self, AtomicReferenceArray<TestAgent> population, Scheduler clock, AtomicLongArray times) {
            super(self);
            this.population = population;
            this.clock = clock;
            this.times = times;
            population.set(self.getProxyID(), self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            TestAgent server = population.get(0);
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 6)) return; continue;
                    case 1:
                        if (self.getProxyID() != 0) {
                            pc = 3;
                            continue;
                        }
                        times.set(0, clock.nanoTime());
                        pc = 2;
                        if (!ctx.waitFor("nothing", 300)) return;
                    case 2:
                        times.set(1, clock.nanoTime());
                        if (!step(ctx, 5)) return;
                        continue;
                    case 3:
                        asking = ctx.invoke(server, "getProxyID", -1, () -> {
                            times.set(2, clock.nanoTime());
                            return server.getProxyID();
                        });
                        pc = 4;
                        if (!ctx.await(asking)) return;
                    case 4:
                        times.set(3, asking.join());
                        if (!step(ctx, 5)) return;
                        continue;
                    case 5: if (!leave(ctx, MAIN, 6)) return; continue;
                    case 6: if (!endOf(ctx, MAIN.sequence(), 7)) return; continue;
                    case 7: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aWaitThatNothingSatisfiesEndsByItsTimeout(Driver driver) {
        AgentType type = TestTypes.testAgent();
        for (int run = 0; run < 3; run++) {
            AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(2);
            AtomicLongArray times = new AtomicLongArray(4);
            times.set(3, -1);
            Scheduler scheduler = driver.newScheduler();
            Missions.run(scheduler, MAIN, 2, type, self -> new Nothing(self, population, scheduler, times), Trace.NONE);
            long waited = times.get(1) - times.get(0);
            assertTrue(waited >= TimeUnit.MILLISECONDS.toNanos(300), "waited " + waited + " ns");
            assertTrue(waited < TimeUnit.SECONDS.toNanos(15), "waited " + waited + " ns");
            assertTrue(times.get(2) >= times.get(1), "served during the wait");
            assertEquals(0, times.get(3), "the queued call was answered after the wait");
        }
    }
}
