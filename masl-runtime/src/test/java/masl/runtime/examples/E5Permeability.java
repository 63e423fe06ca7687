package masl.runtime.examples;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Event;
import masl.runtime.Mode;
import masl.runtime.Reaction;
import masl.runtime.testing.TestAgent;

/**
 * E5 of examples.md, translated by hand. Every primitive call goes through the runtime, which
 * filters it by permeability: internal ones with {@code invokeSelf}, the external one with
 * {@code invoke}, awaited and followed by its step boundary, where the {@code timeout} of the
 * denial is reacted to. The agents' implementations ({@code a}, {@code b}) are in
 * {@code population}, indexed by proxy id, as the generated mission class provides them.
 * <pre>
 *  3 synchronous entry main (true) {
 *  4   local int me = .getProxyID();
 *  5   local int seen = 7;
 *  6   if (me == 1) setAcceptState("nothing"); else .nop();
 *  7   if (me == 0) seen = b.getProxyID();
 *  8   if (me == 0) .logln("seen=" + seen);
 *  9   react (timeout) { .logln("timeout"); resume; }
 * 10 }
 * </pre>
 * Kept by hand as a worked example of the generated-code contract: {@link HandTranslationTest}
 * holds it equal to what the translator makes of examples.md.
 */
final class E5Permeability extends AgentProgram {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    static final Reaction MAIN_REACT_TIMEOUT = MAIN.react(Event.TIMEOUT);

    private final TestAgent self;
    private final AtomicReferenceArray<TestAgent> population;
    private int main$me;
    private int main$seen;
    private CompletableFuture<Integer> tmp$1;

    E5Permeability(TestAgent self, AtomicReferenceArray<TestAgent> population) {
        this.self = self;
        this.population = population;
        population.set(self.getProxyID(), self);
    }

    @Override
    protected int reactionPc(Reaction reaction) {
        if (reaction == MAIN_REACT_TIMEOUT) {
            return 9;
        }
        return super.reactionPc(reaction);
    }

    @Override
    @SuppressWarnings("fallthrough") // resumption points fall through into the next one
    protected void resume(AgentContext ctx) {
        while (true) {
            switch (pc) {
                case 0: // 3: synchronous entry main (true)
                    pc = 1;
                    switch (ctx.enter(MAIN, true)) {
                        case SKIPPED -> { pc = 7; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 1: // 4-5: declarations
                    main$me = ctx.invokeSelf("getProxyID", 0, self::getProxyID);
                    main$seen = 7;
                    // 6: if (me == 1) setAcceptState("nothing"); else .nop();
                    if (main$me == 1) {
                        ctx.setAcceptState("nothing");
                    } else {
                        ctx.invokeSelf("nop", null, () -> {
                            self.nop();
                            return null;
                        });
                    }
                    pc = 2;
                    if (!ctx.stepBoundary()) return;
                case 2: // 7: if (me == 0) seen = b.getProxyID();
                    if (!(main$me == 0)) {
                        pc = 4;
                        continue;
                    }
                    TestAgent b = population.get(1);
                    tmp$1 = ctx.invoke(b, "getProxyID", 0, b::getProxyID);
                    pc = 3;
                    if (!ctx.await(tmp$1)) return;
                case 3:
                    main$seen = tmp$1.join();
                    pc = 4;
                    if (!ctx.stepBoundary()) return;
                case 4: // 8: if (me == 0) .logln("seen=" + seen);
                    if (!(main$me == 0)) {
                        pc = 6;
                        continue;
                    }
                    ctx.invokeSelf("logln", null, () -> {
                        self.logln("seen=" + main$seen);
                        return null;
                    });
                    pc = 5;
                    if (!ctx.stepBoundary()) return;
                case 5:
                case 6: // 10: end of main
                    pc = 7;
                    if (!ctx.leave(MAIN)) return;
                case 7: // after main
                    pc = 8;
                    if (!ctx.endOfSequence(MAIN.sequence())) return;
                case 8:
                    ctx.finish();
                    return;
                case 9: // 9: react (timeout) { .logln("timeout"); resume; }
                    ctx.invokeSelf("logln", null, () -> {
                        self.logln("timeout");
                        return null;
                    });
                    if (!ctx.endReaction()) return;
                    if (!ctx.resumeInterrupted()) return;
                    continue;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
