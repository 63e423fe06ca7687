package masl.runtime.invocation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.AgentContext;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.SharedDeclaration;
import masl.runtime.descriptor.AgentType;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.TestTypes;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * MASL §11, table-driven: for each of the 8 combinations of x bits (u g o) that state {@code xK} of
 * agents/Default.xml gives {@code nop}, the callee (agent 0, in block {@code inner}) takes that
 * state, and {@code nop} is invoked by the callee itself (u), by a member of the same innermost
 * block (g), by an agent in the parent block {@code main} (o) and by one in the sibling block
 * {@code elsewhere} (o). Exactly the allowed invocations run, each once.
 * <pre>
 * asynchronous entry main (true) {
 *   shared int ready = 0; shared int done = 0;
 *   asynchronous entry inner (me &lt;= 1) { if (me == 0) callee(); else request(); }
 *   asynchronous entry elsewhere (me == 3) { request(); }
 *   if (me == 2) request();
 * }
 * callee:  setAcceptState("xK"); ready = 1; while (done &lt; 3) {} .nop();
 * request: while (ready == 0) {} a0.nop(); done++;
 * </pre>
 */
@Timeout(120)
class PermeabilityTableTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final SharedDeclaration<Integer> READY = MAIN.declareShared("ready", 0);
    static final SharedDeclaration<Integer> DONE = MAIN.declareShared("done", 0);
    static final ESequence BLOCKS = MAIN.newSequence();
    static final EntryDefinition INNER = BLOCKS.block("inner", Mode.ASYNCHRONOUS);
    static final EntryDefinition ELSEWHERE = BLOCKS.block("elsewhere", Mode.ASYNCHRONOUS);

    static final class Requests extends CompactProgram {
        private final int bits;
        private final AtomicReferenceArray<TestAgent> population;
        private final AtomicIntegerArray ran;
        private CompletableFuture<Object> request;
        private int back;

        Requests(TestAgent self, int bits, AtomicReferenceArray<TestAgent> population, AtomicIntegerArray ran) {
            super(self);
            this.bits = bits;
            this.population = population;
            this.ran = ran;
            population.set(self.getProxyID(), self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 16)) return; continue;
                    case 1: if (!arrive(ctx, INNER, me <= 1, 2, 9)) return; continue;
                    case 2:
                        if (me != 0) {
                            back = 8;
                            pc = 20;
                            continue;
                        }
                        ctx.setAcceptState("x" + bits);
                        ctx.shared(READY).set(1);
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3: if (!busyWait(ctx, ctx.shared(DONE).get() < 3, 4)) return; continue;
                    case 4:
                        ctx.invokeSelf("nop", null, () -> {
                            ran.incrementAndGet(me);
                            return null;
                        });
                        if (!step(ctx, 8)) return;
                        continue;
                    case 8: if (!leave(ctx, INNER, 9)) return; continue;
                    case 9: if (!arrive(ctx, ELSEWHERE, me == 3, 10, 12)) return; continue;
                    case 10: back = 11; pc = 20; continue;
                    case 11: if (!leave(ctx, ELSEWHERE, 12)) return; continue;
                    case 12: if (!endOf(ctx, BLOCKS, 13)) return; continue;
                    case 13:
                        if (me == 2) {
                            back = 15;
                            pc = 20;
                        } else {
                            pc = 15;
                        }
                        continue;
                    case 15: if (!leave(ctx, MAIN, 16)) return; continue;
                    case 16: if (!endOf(ctx, MAIN.sequence(), 17)) return; continue;
                    case 17: ctx.finish(); return;
                    case 20: if (!busyWait(ctx, ctx.shared(READY).get() == 0, 21)) return; continue;
                    case 21:
                        request = ctx.invoke(population.get(0), "nop", null, () -> {
                            ran.incrementAndGet(me);
                            return null;
                        });
                        pc = 22;
                        if (!ctx.await(request)) return;
                    case 22:
                        ctx.shared(DONE).getAndUpdate(done -> done + 1);
                        if (!step(ctx, back)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void exactlyTheAllowedInvocationsRun(Driver driver) {
        AgentType type = TestTypes.testAgent();
        for (int run = 0; run < Missions.REPETITIONS / 5; run++) {
            for (int bits = 0; bits < 8; bits++) {
                AtomicIntegerArray ran = new AtomicIntegerArray(4);
                int state = bits;
                AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(4);
                Missions.run(driver.newScheduler(), MAIN, 4, type,
                        self -> new Requests(self, state, population, ran), Trace.NONE);
                int u = bits >> 2 & 1;
                int g = bits >> 1 & 1;
                int o = bits & 1;
                assertEquals(u + "" + g + o + o, "" + ran.get(0) + ran.get(1) + ran.get(2) + ran.get(3),
                        "runs by self, same block, parent block, sibling block in state x" + bits);
            }
        }
    }
}
