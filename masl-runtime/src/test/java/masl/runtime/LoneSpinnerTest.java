package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicInteger;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * MASL §5: an iteration of a busy-wait that runs no instruction is a step of its synchronous block,
 * but a member spinning alone there, with nothing it can observe changing, parks instead of tripping
 * its own barrier again and again: it evaluates its condition a few times, however long the others
 * run meanwhile.
 */
@Timeout(120)
class LoneSpinnerTest {

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   shared int go = 0;
     *   synchronous entry spin (.getProxyID() == 0) {
     *     while (go == 0) {}
     *   }
     *   if (.getProxyID() == 1) { nop() STEPS times; go = 1; }
     * }
     * </pre>
     * counting the evaluations of {@code go == 0}. Written by hand: MASL cannot count them, since a
     * primitive call in the condition would make the loop a spinning one, not parked.
     */
    static final class Spinner extends CompactProgram {
        static final int STEPS = 1_000;
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final SharedDeclaration<Integer> GO = MAIN.declareShared("go", 0);
        static final EntryDefinition SPIN = MAIN.child("spin", Mode.SYNCHRONOUS);

        private final AtomicInteger evaluations;
        private int steps;

        Spinner(TestAgent self, AtomicInteger evaluations) {
            super(self);
            this.evaluations = evaluations;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 9)) return; continue;
                    case 1:
                        ctx.shared(GO).initialise(() -> 0);
                        if (!arrive(ctx, SPIN, id == 0, 2, 4)) return;
                        continue;
                    case 2: if (!busyWait(ctx, waiting(ctx), 3)) return; continue;
                    case 3: if (!leave(ctx, SPIN, 4)) return; continue;
                    case 4: if (!endOf(ctx, SPIN.sequence(), 5)) return; continue;
                    case 5:
                        if (id != 1) {
                            pc = 7;
                            continue;
                        }
                        self.nop();
                        if (!step(ctx, ++steps < STEPS ? 5 : 6)) return;
                        continue;
                    case 6: ctx.shared(GO).set(1); if (!step(ctx, 7)) return; continue;
                    case 7: if (!leave(ctx, MAIN, 8)) return; continue;
                    case 8: if (!endOf(ctx, MAIN.sequence(), 9)) return; continue;
                    case 9: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }

        private boolean waiting(AgentContext ctx) {
            evaluations.incrementAndGet();
            return ctx.shared(GO).get() == 0;
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMemberSpinningAloneInASynchronousBlockParksUntilSomethingChanges(Driver driver) {
        for (int run = 0; run < 5; run++) {
            AtomicInteger evaluations = new AtomicInteger();
            Missions.run(driver, Spinner.MAIN, 2, self -> new Spinner(self, evaluations));
            // The first iteration's step, one after each change of memberships or of go: a handful.
            assertTrue(evaluations.get() <= 10, evaluations + " evaluations while agent 1 ran " + Spinner.STEPS + " steps");
        }
    }
}
