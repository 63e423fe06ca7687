package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Objects;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.entry.Entry;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The runtime side of invocations (MASL §5, §9): a blocked or finished callee still serves the
 * invocations queued for it, and a caller waits for a result without holding a thread.
 */
@Timeout(120)
class InvocationServingTest {

    /**
     * Agent 1 (the callee) waits at the entry barrier of a locked block; agent 0 invokes it, logs
     * the result, and then releases the block.
     */
    private static final MaslProgram HELD_CALLEE = MaslProgram.of("held.masl", 2, """
            Entry gate;
            asynchronous entry main (true) {
              scalar entry setup (true) { gate.lock(); }
              while (gate.getLockPolicy() == "free") {}
              asynchronous entry call (.getProxyID() == 0) {
                while (gate.getWaitingInCount() == 0) {}
                .logln("served " + a1.getProxyID());
                gate.release();
              }
              synchronous entry gate (.getProxyID() == 1) { .logln("in gate"); }
            }
            """);

    /**
     * Agent 1 (the callee) waits at the entry barrier of a locked block, or skips main and
     * finishes; agent 0 invokes it, waits for the result with {@code await}, logs it, and then
     * releases the block. Written by hand for the callee that finishes first: the caller waits
     * until the callee's program has finished, which no MASL expression sees.
     */
    static final class CallerAndCallee extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final EntryDefinition SETUP = MAIN.child("setup", Mode.SCALAR);
        static final ESequence CALL_GATE = MAIN.newSequence();
        static final EntryDefinition CALL = CALL_GATE.block("call", Mode.ASYNCHRONOUS);
        static final EntryDefinition GATE = CALL_GATE.block("gate", Mode.SYNCHRONOUS);

        private final AtomicReferenceArray<AgentContext> agents;
        private final boolean calleeFinishesFirst;
        private final AtomicBoolean calleeFinishing;
        private CompletableFuture<String> result;

        CallerAndCallee(TestAgent self, AtomicReferenceArray<AgentContext> agents, boolean calleeFinishesFirst,
                AtomicBoolean calleeFinishing) {
            super(self);
            this.agents = agents;
            this.calleeFinishesFirst = calleeFinishesFirst;
            this.calleeFinishing = calleeFinishing;
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            Entry gate = ctx.entry(GATE);
            while (true) {
                switch (pc) {
                    case 0:
                        agents.set(id, ctx);
                        if (!arrive(ctx, MAIN, id == 0 || !calleeFinishesFirst, 1, 15)) return;
                        continue;
                    case 1: if (!arrive(ctx, SETUP, true, 2, 3)) return; continue;
                    case 2: gate.lock(); if (!leave(ctx, SETUP, 3)) return; continue;
                    case 3: if (!endOf(ctx, SETUP.sequence(), 4)) return; continue;
                    case 4: if (!busyWait(ctx, Objects.equals(gate.getLockPolicy(), "free"), 5)) return; continue;
                    case 5: if (!arrive(ctx, CALL, id == 0, 6, 10)) return; continue;
                    case 6:
                        if (calleeFinishesFirst) {
                            // A spin: the flag is no state the runtime sees change.
                            if (calleeFinishing.get()) {
                                pc = 7;
                                continue;
                            }
                            if (!ctx.loopIteration()) return;
                            continue;
                        }
                        if (!busyWait(ctx, gate.getWaitingInCount() == 0, 7)) return;
                        continue;
                    case 7:
                        TestAgent callee = (TestAgent) ((Agent) agents.get(1)).implementation;
                        result = ctx.invoke(callee, "nop", "", () -> "served");
                        pc = 8;
                        if (!ctx.await(result)) return;
                    case 8:
                        self.logln(result.join());
                        gate.release();
                        if (!step(ctx, 9)) return;
                        continue;
                    case 9: if (!leave(ctx, CALL, 10)) return; continue;
                    case 10:
                        if (!arrive(ctx, GATE, id == 1 && !calleeFinishesFirst, 11, 13)) return;
                        continue;
                    case 11: self.logln("in gate"); if (!step(ctx, 12)) return; continue;
                    case 12: if (!leave(ctx, GATE, 13)) return; continue;
                    case 13: if (!endOf(ctx, CALL_GATE, 14)) return; continue;
                    case 14: if (!leave(ctx, MAIN, 15)) return; continue;
                    case 15: if (!endOf(ctx, MAIN.sequence(), 16)) return; continue;
                    case 16:
                        if (id == 1) {
                            calleeFinishing.set(true);
                        }
                        ctx.finish();
                        return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aCalleeBlockedAtAnEntryBarrierStillServesItsCallers(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("served 1\nin gate\n", HELD_CALLEE.run(driver).journal());
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aCalleeThatHasLeftMainStillServesItsCallers(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            AtomicReferenceArray<AgentContext> agents = new AtomicReferenceArray<>(2);
            AtomicBoolean calleeFinishing = new AtomicBoolean();
            String journal = Missions.run(driver, CallerAndCallee.MAIN, 2,
                    self -> new CallerAndCallee(self, agents, true, calleeFinishing)).journal();
            assertEquals("served\n", journal);
        }
    }
}
