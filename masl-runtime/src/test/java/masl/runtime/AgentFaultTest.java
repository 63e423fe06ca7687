package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Agent faults: a primitive that hangs past the call timeout gives {@code timeout} and its
 * default value, internal, external or launched; one that throws gives {@code uncaught_exception};
 * an agent whose program dies leaves its blocks, the others go on, the trace says why.
 */
@Timeout(120)
class AgentFaultTest {

    /**
     * Long enough that a primitive which throws at once never reaches it, even on a machine whose
     * threads wait tens of milliseconds for a core; each hung call costs this much.
     */
    private static final Duration CALL_TIMEOUT = Duration.ofMillis(250);
    private static final int REPETITIONS = 10;
    /** Runs of the missions that wait for {@link #CALL_TIMEOUT}. */
    private static final int TIMED_OUT_REPETITIONS = 3;

    /**
     * A primitive that never returns by itself: it waits until its thread is interrupted. Once timed
     * out, it must end, its thread interrupted.
     */
    private static final class Hang {
        private final AtomicReference<Thread> runner = new AtomicReference<>();

        int call() throws InterruptedException {
            runner.set(Thread.currentThread());
            new CountDownLatch(1).await();
            return 42;
        }

        /** Whether the thread that ran the call, if any, has ended within 10 s. */
        boolean ended() throws InterruptedException {
            Thread thread = runner.get();
            if (thread != null) {
                thread.join(10_000);
            }
            return thread == null || !thread.isAlive();
        }
    }

    /**
     * <pre>
     * synchronous entry main (true) {
     *   v = .hang();  .logln("v=" + v);          // internal
     *   l = .hang();  (launched, asynchronous)   then await it, .logln("l=" + l)
     *   w = .fail();  .logln("w=" + w);
     *   react (timeout) { .logln("timeout " + getMessageFromEvent(timeout)); resume; }
     *   react (uncaught_exception) { .logln("uncaught " + …); resume; }
     * }
     * </pre>
     */
    static final class Calls extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final Reaction ON_TIMEOUT = MAIN.react(Event.TIMEOUT);
        static final Reaction ON_UNCAUGHT = MAIN.react(Event.UNCAUGHT_EXCEPTION);

        final Hang internal = new Hang();
        final Hang launched = new Hang();
        private CompletableFuture<Integer> launch;

        Calls(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == ON_TIMEOUT ? 20 : reaction == ON_UNCAUGHT ? 21 : super.reactionPc(reaction);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 6)) return; continue;
                    case 1:
                        self.logln("v=" + ctx.invokeSelf("hang", 7, internal::call));
                        if (!step(ctx, 2)) return;
                    case 2:
                        launch = ctx.launch(self, "hang", 8, launched::call);
                        pc = 3;
                        if (!ctx.await(launch)) return;
                    case 3:
                        self.logln("l=" + launch.join());
                        if (!step(ctx, 4)) return;
                    case 4:
                        self.logln("w=" + ctx.invokeSelf("fail", 9, () -> {
                            throw new IllegalStateException("fails");
                        }));
                        if (!step(ctx, 5)) return;
                    case 5: if (!leave(ctx, MAIN, 6)) return;
                    case 6: if (!endOf(ctx, MAIN.sequence(), 7)) return;
                    case 7: ctx.finish(); return;
                    case 20:
                        self.logln("timeout " + ctx.messageOf(Event.TIMEOUT));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    case 21:
                        self.logln("uncaught " + ctx.messageOf(Event.UNCAUGHT_EXCEPTION));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aHungPrimitiveGivesTimeoutAndItsDefaultAndOneThatThrowsUncaughtException(Driver driver) throws Exception {
        for (int run = 0; run < TIMED_OUT_REPETITIONS; run++) {
            Calls[] program = new Calls[1];
            MissionOutcome outcome = Mission.builder().main(Calls.MAIN).scheduler(driver.newScheduler())
                    .callTimeout(CALL_TIMEOUT)
                    .agent("a", new TestAgent(), self -> program[0] = new Calls(self))
                    .build().run(Duration.ofSeconds(20));
            assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
            assertEquals("v=7\ntimeout hang\nl=8\ntimeout hang\nw=9\nuncaught java.lang.IllegalStateException\n",
                    outcome.journal());
            // The hung calls' threads were interrupted: none is left running.
            assertTrue(program[0].internal.ended());
            assertTrue(program[0].launched.ended());
        }
    }

    /**
     * Agent 0 calls agent 1's hanging primitive; agent 1 has finished and serves it on its behalf.
     * <pre>
     * asynchronous entry main (true) {
     *   if (me == 0) { w = a1.hang(); .logln("w=" + w); }
     *   react (timeout) { .logln("timeout " + getMessageFromEvent(timeout)); resume; }
     * }
     * </pre>
     */
    static final class ExternalCall extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Reaction ON_TIMEOUT = MAIN.react(Event.TIMEOUT);

        private final AtomicReferenceArray<TestAgent> population;
        private final Hang hang;
        private CompletableFuture<Integer> call;

        ExternalCall(TestAgent self, AtomicReferenceArray<TestAgent> population, Hang hang) {
            super(self);
            this.population = population;
            this.hang = hang;
            population.set(self.getProxyID(), self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == ON_TIMEOUT ? 20 : super.reactionPc(reaction);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 4)) return; continue;
                    case 1:
                        if (self.getProxyID() != 0) {
                            pc = 3;
                            continue;
                        }
                        call = ctx.invoke(population.get(1), "hang", 8, hang::call);
                        pc = 2;
                        if (!ctx.await(call)) return;
                    case 2:
                        self.logln("w=" + call.join());
                        if (!step(ctx, 3)) return;
                    case 3: if (!leave(ctx, MAIN, 4)) return;
                    case 4: if (!endOf(ctx, MAIN.sequence(), 5)) return;
                    case 5: ctx.finish(); return;
                    case 20:
                        self.logln("timeout " + ctx.messageOf(Event.TIMEOUT));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anExternalCallPastTheTimeoutGivesTimeoutInTheCaller(Driver driver) throws Exception {
        for (int run = 0; run < TIMED_OUT_REPETITIONS; run++) {
            AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(2);
            Hang hang = new Hang();
            Mission.Builder builder = Mission.builder().main(ExternalCall.MAIN).scheduler(driver.newScheduler())
                    .callTimeout(CALL_TIMEOUT);
            for (int i = 0; i < 2; i++) {
                builder.agent("a" + i, new TestAgent(), self -> new ExternalCall(self, population, hang));
            }
            MissionOutcome outcome = builder.build().run(Duration.ofSeconds(20));
            assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
            assertEquals("w=8\ntimeout hang\n", outcome.journal());
            assertTrue(hang.ended());
        }
    }

    /**
     * Three agents in lock-step for {@code STEPS} instructions; agent 1's program throws at its third.
     * <pre>
     * synchronous entry main (true) {
     *   for (i = 0; i &lt; STEPS; i++) { if (me == 1 &amp;&amp; i == 2) throw …; .logln(me + ":" + i); }
     * }
     * </pre>
     */
    static final class Dying extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final int STEPS = 6;

        private final Throwable cause;
        private int i;

        Dying(TestAgent self, Throwable cause) {
            super(self);
            this.cause = cause;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 3)) return; continue;
                    case 1:
                        if (i == STEPS) {
                            pc = 2;
                            continue;
                        }
                        if (self.getProxyID() == 1 && i == 2) {
                            throwUnchecked(cause);
                        }
                        self.logln(self.getProxyID() + ":" + i++);
                        if (!step(ctx, 1)) return;
                        continue;
                    case 2: if (!leave(ctx, MAIN, 3)) return; continue;
                    case 3: if (!endOf(ctx, MAIN.sequence(), 4)) return; continue;
                    case 4: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }

        @Override
        protected String sourceAt(int pc) {
            return pc == 1 ? "dying.masl:3: .logln(me + \":\" + i);" : null;
        }

        private static void throwUnchecked(Throwable cause) {
            if (cause instanceof Error error) {
                throw error;
            }
            throw (RuntimeException) cause;
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anAgentWhoseProgramDiesLeavesItsBlocksAndTheOthersGoOn(Driver driver) throws Exception {
        for (Throwable cause : List.of(new AssertionError("boom"), new ArithmeticException("/ by zero"))) {
            for (int run = 0; run < REPETITIONS; run++) {
                MemoryTrace trace = new MemoryTrace();
                Mission.Builder builder = Mission.builder().main(Dying.MAIN).scheduler(driver.newScheduler()).trace(trace);
                for (int i = 0; i < 3; i++) {
                    builder.agent("a" + i, new TestAgent(), self -> new Dying(self, cause));
                }
                MissionOutcome outcome = builder.build().run(Duration.ofSeconds(20));

                assertEquals(MissionOutcome.Status.FAILED, outcome.status(), outcome::toString);
                assertEquals(cause, outcome.failure().orElseThrow().getCause());
                List<String> journal = outcome.journal().lines().toList();
                for (int step = 0; step < Dying.STEPS; step++) {
                    assertTrue(journal.contains("0:" + step) && journal.contains("2:" + step), outcome.journal());
                }
                assertEquals(List.of("1:0", "1:1"), journal.stream().filter(line -> line.startsWith("1:")).toList());

                List<TraceEvent> events = trace.events();
                TraceEvent.AgentFailed failed = trace.events(TraceEvent.AgentFailed.class).get(0);
                assertEquals(new TraceEvent.AgentFailed(failed.nanos(), 1, cause.toString(),
                        "dying.masl:3: .logln(me + \":\" + i);"), failed);
                int failedAt = events.indexOf(failed);
                TraceEvent left = events.get(failedAt + 1);
                assertTrue(left instanceof TraceEvent.Left l && l.agent() == 1 && l.cause() == LeaveCause.FAILED,
                        events::toString);
                // Every trip after agent 1 left is of the two others.
                events.subList(failedAt, events.size()).stream()
                        .filter(TraceEvent.BarrierTripped.class::isInstance)
                        .forEach(trip -> assertEquals(2, ((TraceEvent.BarrierTripped) trip).agents(), events::toString));
            }
        }
    }

    @Test
    void aCallTimeoutMustBePositive() {
        try {
            Mission.builder().callTimeout(Duration.ZERO);
        } catch (IllegalArgumentException expected) {
            assertTrue(expected.getMessage().contains("positive"));
            return;
        }
        throw new AssertionError("a zero call timeout was accepted");
    }
}
