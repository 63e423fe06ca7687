package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Missions: outcomes, journal, contract violations, restart. */
@Timeout(60)
class MissionTest {

    /** {@code asynchronous entry main (true) { local int k = 0; asynchronous entry b (true) { k++; if (k < 3) restart; } .logln(k); }} */
    static final class Restart extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final EntryDefinition B = MAIN.child("b", Mode.ASYNCHRONOUS);

        private int k;

        Restart(TestAgent self) {
            super(self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 9)) return; continue;
                    case 1: k = 0; pc = 2; continue;
                    case 2: if (!arrive(ctx, B, true, 3, 6)) return; continue;
                    case 3: k++; if (!step(ctx, 4)) return; continue;
                    case 4:
                        if (k < 3) {
                            ctx.restart(B);
                            pc = 3;
                            continue;
                        }
                        pc = 5;
                        continue;
                    case 5: if (!leave(ctx, B, 6)) return; continue;
                    case 6: if (!endOf(ctx, B.sequence(), 7)) return; continue;
                    case 7: self.logln(String.valueOf(k)); if (!step(ctx, 8)) return; continue;
                    case 8: if (!leave(ctx, MAIN, 9)) return; continue;
                    case 9: if (!endOf(ctx, MAIN.sequence(), 10)) return; continue;
                    case 10: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void restartKeepsMembershipAndLocals(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("3\n3\n", Missions.run(driver, Restart.MAIN, 2, Restart::new, trace).journal());
            assertEquals(2, trace.events(TraceEvent.Entered.class).stream().filter(e -> e.block().equals("b")).count());
            assertEquals(List.of(LeaveCause.END, LeaveCause.END), trace.events(TraceEvent.Left.class).stream()
                    .filter(e -> e.block().equals("b")).map(TraceEvent.Left::cause).toList());
        }
    }

    /** A synchronous main whose agents log, then wait at a locked child nobody releases. */
    static final class Stuck extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final EntryDefinition CHILD = MAIN.child("child", Mode.SYNCHRONOUS);

        Stuck(TestAgent self) {
            super(self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            switch (pc) {
                case 0:
                    if (!arrive(ctx, MAIN, true, 1, 1)) return;
                case 1:
                    self.log("x");
                    ctx.entry(CHILD).lock();
                    arrive(ctx, CHILD, true, 2, 2);
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }

    @Test
    void aMissionWhoseAgentsCanNoLongerProgressIsReportedAsDeadlocked() throws InterruptedException {
        StringWriter sink = new StringWriter();
        Mission.Builder builder = Mission.builder().main(Stuck.MAIN).journal(sink);
        builder.agent("a", new TestAgent(), Stuck::new).agent("b", new TestAgent(), Stuck::new);
        MissionOutcome outcome = builder.build().run(Duration.ofSeconds(30));
        assertEquals(MissionOutcome.Status.DEADLOCKED, outcome.status());
        assertEquals("xx", outcome.journal());
        assertEquals("xx", sink.toString());
        assertTrue(outcome.report().contains("agent a (0) at pc 2: [main, child(waiting-in)]"), outcome.report());
        assertTrue(outcome.report().contains("agent b (1) at pc 2: [main, child(waiting-in)]"), outcome.report());
        MissionOutcome.MissionFailedException failure =
                assertThrows(MissionOutcome.MissionFailedException.class, outcome::requireCompleted);
        assertTrue(failure.getMessage().startsWith("mission DEADLOCKED"), failure.getMessage());
    }

    /** {@code asynchronous entry main (true) { while (true) {} }}: busy, never idle, never done. */
    static final class Endless extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);

        Endless(TestAgent self) {
            super(self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 1)) return; continue;
                    case 1: if (!ctx.loopIteration()) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMissionThatDoesNotEndInTimeTimesOut(Driver driver) throws InterruptedException {
        Mission mission = Mission.builder().main(Endless.MAIN).scheduler(driver.newScheduler())
                .agent("a", new TestAgent(), Endless::new).build();
        MissionOutcome outcome = mission.run(Duration.ofMillis(300));
        assertEquals(MissionOutcome.Status.TIMED_OUT, outcome.status());
        assertTrue(outcome.report().contains("agent a (0) at pc 1: [main]"), outcome.report());
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMissionStoppedFromOutsideEndsAsStopped(Driver driver) throws InterruptedException {
        CountDownLatch running = new CountDownLatch(1);
        Mission mission = Mission.builder().scheduler(driver.newScheduler())
                .agent("a", new TestAgent(), self -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        while (true) {
                            running.countDown();
                            if (!ctx.loopIteration()) return;
                        }
                    }
                }).build();
        Thread stopper = new Thread(() -> {
            try {
                running.await();
                mission.stop();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        stopper.start();
        assertEquals(MissionOutcome.Status.STOPPED, mission.run(Duration.ofSeconds(30)).status());
        stopper.join();
    }

    @Test
    void aProgramThatReturnsWithoutSuspendingFailsTheMission() throws InterruptedException {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        MissionOutcome outcome = Mission.builder().main(main)
                .agent("a", new TestAgent(), self -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        pc = 1;
                    }
                })
                .build().run(Duration.ofSeconds(10));
        assertEquals(MissionOutcome.Status.FAILED, outcome.status());
        assertTrue(outcome.failure().orElseThrow().getCause().getMessage()
                .contains("resume returned without a suspension or finish()"));
    }

    @Test
    void aProgramThatThrowsFailsTheMissionWithItsException() throws InterruptedException {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        ArithmeticException thrown = new ArithmeticException("/ by zero");
        MissionOutcome outcome = Mission.builder().main(main)
                .agent("a", new TestAgent(), self -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        throw thrown;
                    }
                })
                .build().run(Duration.ofSeconds(10));
        assertEquals(MissionOutcome.Status.FAILED, outcome.status());
        assertEquals(thrown, outcome.failure().orElseThrow().getCause());
    }

    @Test
    void aProgramWithoutMainOnlyCreatesItsAgents() throws InterruptedException {
        MissionOutcome outcome = Mission.builder()
                .agent("a", new TestAgent(), self -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        ctx.finish();
                    }
                })
                .build().run(Duration.ofSeconds(10));
        assertEquals(MissionOutcome.Status.COMPLETED, outcome.status());
        assertEquals("", outcome.journal());
    }

    @Test
    void anImplementationIsBoundToOneAgentOnly() {
        TestAgent shared = new TestAgent();
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        Mission.Builder builder = Mission.builder().main(main)
                .agent("a", shared, Stuck::new).agent("b", shared, Stuck::new);
        assertThrows(IllegalStateException.class, builder::build);
    }

    @Test
    void blocksAreNestedAsTheLanguageAllows() {
        EntryDefinition main = EntryDefinition.main("main", Mode.SCALAR);
        assertThrows(IllegalArgumentException.class, () -> main.child("y", Mode.SYNCHRONOUS));
        assertThrows(IllegalArgumentException.class, () -> main.sequence().block("other", Mode.SCALAR));
        assertEquals(List.of(main.child("s", Mode.SCALAR)), main.children());
    }
}
