package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.JsonLinesTrace;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * External invocations (MASL §5, §9): the caller waits for the result without holding a thread,
 * the callee serves at its boundaries or, blocked, on its behalf; a primitive's exception becomes
 * {@code uncaught_exception} in the caller, whose call then gives the default value.
 */
@Timeout(120)
class ExternalInvocationTest {

    static final int ROUNDS = 3;

    /**
     * Two agents in one synchronous block call each other {@link #ROUNDS} times, each call an
     * instruction: every call finds the callee awaiting its own call, or at the barrier, and is served.
     */
    private static final MaslProgram MUTUAL = MaslProgram.of("mutual.masl", 2, """
            synchronous entry main (true) {
              local int r;
              for (r = 0; r < %d; r++) {
                if (.getProxyID() == 0) .logln("0 saw " + a1.getProxyID()); else .logln("1 saw " + a0.getProxyID());
              }
            }
            """.formatted(ROUNDS));

    @ParameterizedTest
    @EnumSource(Driver.class)
    void twoAgentsCallingEachOtherInASynchronousBlockNeverDeadlock(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            StringWriter trace = new StringWriter();
            String journal = MUTUAL.run(driver.newScheduler(), new JsonLinesTrace(trace)).journal();
            assertEquals(List.of("0 saw 1", "0 saw 1", "0 saw 1", "1 saw 0", "1 saw 0", "1 saw 0"),
                    journal.lines().sorted().toList(), journal);
            assertTrue(trace.toString().contains(
                    "\"event\":\"invocation-made\",\"requester\":0,\"callee\":1,\"member\":\"getProxyID\""),
                    trace::toString);
            assertTrue(trace.toString().contains(
                    "\"event\":\"invocation-served\",\"requester\":1,\"callee\":0,\"member\":\"getProxyID\""),
                    trace::toString);
        }
    }

    /**
     * Agent 0 invokes {@code divide} of {@code target}, which throws; agent 1 is parked at the exit
     * barrier by then, or not yet there.
     */
    private static final String THROWING = """
            synchronous entry main (true) {
              local int v = 7;
              local Default target = %s;
              if (.getProxyID() == 0) { v = target.divide(1, 0); .logln("v=" + v); }
              react (uncaught_exception) { .logln(getMessageFromEvent(uncaught_exception)); resume; }
            }
            """;

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aPrimitivesExceptionBecomesUncaughtExceptionInTheCallerWithTheDefaultValue(Driver driver) {
        MaslProgram throwing = MaslProgram.of("throwing.masl", 2, THROWING.formatted("a1"));
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            // The reaction at the call's step boundary, then the value: the type's default.
            assertEquals("java.lang.ArithmeticException\nv=0\n", throwing.run(driver).journal());
        }
    }

    /** {@code a.m()} with {@code a} holding no agent: as a Java call that throws, not a failed mission. */
    @ParameterizedTest
    @EnumSource(Driver.class)
    void invokingAnAgentVariableHoldingNullIsAnUncaughtException(Driver driver) {
        MaslProgram throwing = MaslProgram.of("throwing.masl", 2, THROWING.formatted("null"));
        assertEquals("java.lang.NullPointerException\nv=0\n", throwing.run(driver).journal());
    }

    /**
     * Agent 0 calls agent 1 while agent 1 is stuck at the synchronisation barrier of {@code pair},
     * waiting for agent 2, which busy-waits until that call has been answered: only serving on the
     * callee's behalf lets the mission end.
     * <pre>
     * asynchronous entry main (true) {
     *   shared int looping = 0; shared int served = 0; shared int arrived = 0;
     *   arrived++; while (arrived &lt; 3) {}            // pair's first wave is the whole team
     *   synchronous entry pair (me != 0) {
     *     .nop();
     *     if (me == 1) .nop();                        // then stuck at the barrier
     *     else { while (served == 0) {} .nop(); }     // sets looping = 1 as a test signal
     *   }
     *   if (me == 0) {
     *     wait until looping == 1 and agent 1 is parked;
     *     .logln("served " + a1.getProxyID()); served = 1;
     *   }
     * }
     * </pre>
     * Written by hand: agent 0 calls only once agent 1 is parked ({@code Agent.isIdle}), which no
     * MASL program can observe.
     */
    static final class StuckCallee extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final SharedDeclaration<Integer> LOOPING = MAIN.declareShared("looping", 0);
        static final SharedDeclaration<Integer> SERVED = MAIN.declareShared("served", 0);
        static final SharedDeclaration<Integer> ARRIVED = MAIN.declareShared("arrived", 0);
        static final EntryDefinition PAIR = MAIN.child("pair", Mode.SYNCHRONOUS);

        private final AtomicReferenceArray<TestAgent> population;
        private final AtomicReferenceArray<AgentContext> contexts;
        private CompletableFuture<Integer> call;

        StuckCallee(TestAgent self, AtomicReferenceArray<TestAgent> population,
                AtomicReferenceArray<AgentContext> contexts) {
            super(self);
            this.population = population;
            this.contexts = contexts;
            population.set(self.getProxyID(), self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0:
                        contexts.set(me, ctx);
                        if (!arrive(ctx, MAIN, true, 20, 12)) return;
                        continue;
                    case 20:
                        ctx.shared(ARRIVED).getAndUpdate(arrived -> arrived + 1);
                        if (!step(ctx, 21)) return;
                        continue;
                    case 21: if (!busyWait(ctx, ctx.shared(ARRIVED).get() < 3, 1)) return; continue;
                    case 1: if (!arrive(ctx, PAIR, me != 0, 2, 6)) return; continue;
                    case 2: self.nop(); if (!step(ctx, 3)) return; continue;
                    case 3:
                        if (me == 1) {
                            self.nop();
                            if (!step(ctx, 5)) return;
                            continue;
                        }
                        ctx.shared(LOOPING).set(1);
                        pc = 4;
                    case 4: if (!busyWait(ctx, ctx.shared(SERVED).get() == 0, 41)) return; continue;
                    case 41: self.nop(); if (!step(ctx, 5)) return; continue;
                    case 5: if (!leave(ctx, PAIR, 6)) return; continue;
                    case 6: if (!endOf(ctx, PAIR.sequence(), 7)) return; continue;
                    case 7:
                        if (me != 0) {
                            pc = 11;
                            continue;
                        }
                        if (ctx.shared(LOOPING).get() == 0 || !((Agent) contexts.get(1)).isIdle()) {
                            if (!loop(ctx, 7)) return;
                            continue;
                        }
                        TestAgent callee = population.get(1);
                        call = ctx.invoke(callee, "getProxyID", -1, callee::getProxyID);
                        pc = 8;
                        if (!ctx.await(call)) return;
                    case 8:
                        self.logln("served " + call.join());
                        ctx.shared(SERVED).set(1);
                        if (!step(ctx, 11)) return;
                        continue;
                    case 11: if (!leave(ctx, MAIN, 12)) return; continue;
                    case 12: if (!endOf(ctx, MAIN.sequence(), 13)) return; continue;
                    case 13: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aCalleeStuckAtASynchronisationBarrierServesItsCaller(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(3);
            AtomicReferenceArray<AgentContext> contexts = new AtomicReferenceArray<>(3);
            String journal = Missions.run(driver, StuckCallee.MAIN, 3,
                    self -> new StuckCallee(self, population, contexts)).journal();
            assertEquals("served 1\n", journal);
        }
    }
}
