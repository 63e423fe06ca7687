package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
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
     * An agent whose {@code hang}, and its {@code measure} launched asynchronously, never return by
     * themselves. Once timed out, each must end, its thread interrupted.
     */
    private static final class Hanging extends TestAgent {
        private final List<Thread> runners = new CopyOnWriteArrayList<>();

        @Override
        public int hang() {
            runners.add(Thread.currentThread());
            return super.hang();
        }

        @Override
        public int measure() {
            return hang();
        }

        /** How many calls hung, once the threads that ran them, if any, have ended within 10 s. */
        int ended() throws InterruptedException {
            for (Thread thread : runners) {
                thread.join(10_000);
                assertTrue(!thread.isAlive(), "a timed-out primitive's thread still runs");
            }
            return runners.size();
        }
    }

    private static final MaslProgram CALLS = MaslProgram.of("calls.masl", 1, """
            synchronous entry main (true) {
              local int v = 7;
              local int l = 8;
              local int w = 9;
              v = .hang(); .logln("v=" + v);
              l = .measure(); .logln("l=" + l);
              w = .divide(1, 0); .logln("w=" + w);
              react (timeout) { .logln("timeout " + getMessageFromEvent(timeout)); resume; }
              react (uncaught_exception) { .logln("uncaught " + getMessageFromEvent(uncaught_exception)); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aHungPrimitiveGivesTimeoutAndItsDefaultAndOneThatThrowsUncaughtException(Driver driver) throws Exception {
        for (int run = 0; run < TIMED_OUT_REPETITIONS; run++) {
            Hanging agent = new Hanging();
            MissionOutcome outcome = CALLS.newMission(() -> agent).scheduler(driver.newScheduler())
                    .callTimeout(CALL_TIMEOUT).build().run(Duration.ofSeconds(20));
            assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
            assertEquals("timeout hang\nv=0\nl=0\ntimeout measure\nuncaught java.lang.ArithmeticException\nw=0\n",
                    outcome.journal());
            // The hung calls' threads were interrupted: none is left running.
            assertEquals(2, agent.ended());
        }
    }

    /** Agent 0 calls agent 1's hanging primitive; agent 1 has finished and serves it on its behalf. */
    private static final MaslProgram EXTERNAL_CALL = MaslProgram.of("external.masl", 2, """
            asynchronous entry main (true) {
              local int w = 8;
              if (.getProxyID() == 0) { w = a1.hang(); .logln("w=" + w); }
              react (timeout) { .logln("timeout " + getMessageFromEvent(timeout)); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anExternalCallPastTheTimeoutGivesTimeoutInTheCaller(Driver driver) throws Exception {
        for (int run = 0; run < TIMED_OUT_REPETITIONS; run++) {
            List<Hanging> agents = new ArrayList<>();
            MissionOutcome outcome = EXTERNAL_CALL.newMission(MaslProgram.recording(Hanging::new, agents))
                    .scheduler(driver.newScheduler()).callTimeout(CALL_TIMEOUT).build().run(Duration.ofSeconds(20));
            assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
            assertEquals("timeout hang\nw=0\n", outcome.journal());
            assertEquals(List.of(0, 1), List.of(agents.get(0).ended(), agents.get(1).ended()));
        }
    }

    /** Three agents in lock-step for six instructions; agent 1's program dies at its third. */
    private static final MaslProgram DYING = MaslProgram.of("dying.masl", 3, """
            synchronous entry main (true) {
              local int i = 0;
              for (i = 0; i < 6; i++) .logln(.getProxyID() + ":" + i);
            }
            """);
    private static final int STEPS = 6;
    private static final String DIES_AT = "dying.masl:5: .logln(.getProxyID() + \":\" + i);";

    /** An agent whose program dies of {@code cause} where it would log "1:2": an Error escapes the call. */
    private static final class Dying extends TestAgent {
        private final Error cause;

        Dying(Error cause) {
            this.cause = cause;
        }

        @Override
        public void logln(String message) {
            if (message.equals("1:2")) {
                throw cause;
            }
            super.logln(message);
        }
    }

    /**
     * The same program written by hand, for a cause MASL cannot let escape: every {@link Exception}
     * of a call in MASL becomes {@code uncaught_exception} (§8), so only the runtime or a program
     * broken by hand dies of one.
     */
    static final class DyingOfException extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);

        private final RuntimeException cause;
        private int i;

        DyingOfException(TestAgent self, RuntimeException cause) {
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
                            throw cause;
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
            return pc == 1 ? DIES_AT : null;
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anAgentWhoseProgramDiesLeavesItsBlocksAndTheOthersGoOn(Driver driver) throws Exception {
        for (Throwable cause : List.of(new AssertionError("boom"), new ArithmeticException("/ by zero"))) {
            for (int run = 0; run < REPETITIONS; run++) {
                MemoryTrace trace = new MemoryTrace();
                Mission.Builder builder;
                if (cause instanceof Error error) {
                    builder = DYING.newMission(() -> new Dying(error));
                } else {
                    builder = Mission.builder().main(DyingOfException.MAIN);
                    for (int i = 0; i < 3; i++) {
                        builder.agent("a" + i, new TestAgent(), self -> new DyingOfException(self, (RuntimeException) cause));
                    }
                }
                MissionOutcome outcome = builder.scheduler(driver.newScheduler()).trace(trace).build().run(Duration.ofSeconds(20));

                assertEquals(MissionOutcome.Status.FAILED, outcome.status(), outcome::toString);
                assertEquals(cause, outcome.failure().orElseThrow().getCause());
                List<String> journal = outcome.journal().lines().toList();
                for (int step = 0; step < STEPS; step++) {
                    assertTrue(journal.contains("0:" + step) && journal.contains("2:" + step), outcome.journal());
                }
                assertEquals(List.of("1:0", "1:1"), journal.stream().filter(line -> line.startsWith("1:")).toList());

                List<TraceEvent> events = trace.events();
                TraceEvent.AgentFailed failed = trace.events(TraceEvent.AgentFailed.class).get(0);
                assertEquals(new TraceEvent.AgentFailed(failed.nanos(), 1, cause.toString(), DIES_AT), failed);
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
