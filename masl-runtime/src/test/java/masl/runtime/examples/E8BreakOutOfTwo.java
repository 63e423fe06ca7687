package masl.runtime.examples;

import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.testing.TestAgent;

/**
 * E8 of examples.md, translated by hand:
 * <pre>
 *  3 asynchronous entry main (true) {
 *  4   asynchronous entry outer (true) {
 *  5     asynchronous entry inner (true) {
 *  6       .logln("in");
 *  7       break(outer);
 *  8       .logln("never");
 *  9     }
 * 10     .logln("never");
 * 11   }
 * 12   .logln("out");
 * 13 }
 * </pre>
 * Kept by hand as a worked example of the generated-code contract: {@link HandTranslationTest}
 * holds it equal to what the translator makes of examples.md.
 */
final class E8BreakOutOfTwo extends AgentProgram {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final EntryDefinition OUTER = MAIN.child("outer", Mode.ASYNCHRONOUS);
    static final EntryDefinition INNER = OUTER.child("inner", Mode.ASYNCHRONOUS);

    private final TestAgent self;

    E8BreakOutOfTwo(TestAgent self) {
        this.self = self;
    }

    @Override
    @SuppressWarnings("fallthrough") // resumption points fall through into the next one
    protected void resume(AgentContext ctx) {
        while (true) {
            switch (pc) {
                case 0: // 3: asynchronous entry main (true)
                    pc = 1;
                    switch (ctx.enter(MAIN, true)) {
                        case SKIPPED -> { pc = 13; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 1: // 4: asynchronous entry outer (true)
                    pc = 2;
                    switch (ctx.enter(OUTER, true)) {
                        case SKIPPED -> { pc = 10; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 2: // 5: asynchronous entry inner (true)
                    pc = 3;
                    switch (ctx.enter(INNER, true)) {
                        case SKIPPED -> { pc = 7; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 3: // 6: .logln("in");
                    self.logln("in");
                    pc = 4;
                    if (!ctx.stepBoundary()) return;
                case 4: // 7: break(outer);
                    ctx.breakOut(OUTER);
                    pc = 10;
                    continue;
                case 5: // 8: .logln("never");
                    self.logln("never");
                    pc = 6;
                    if (!ctx.stepBoundary()) return;
                case 6: // 9: end of inner
                    pc = 7;
                    if (!ctx.leave(INNER)) return;
                case 7: // 9: end of the e-sequence {inner}
                    pc = 8;
                    if (!ctx.endOfSequence(INNER.sequence())) return;
                case 8: // 10: .logln("never");
                    self.logln("never");
                    pc = 9;
                    if (!ctx.stepBoundary()) return;
                case 9: // 11: end of outer
                    pc = 10;
                    if (!ctx.leave(OUTER)) return;
                case 10: // 11: end of the e-sequence {outer}
                    pc = 11;
                    if (!ctx.endOfSequence(OUTER.sequence())) return;
                case 11: // 12: .logln("out");
                    self.logln("out");
                    pc = 12;
                    if (!ctx.stepBoundary()) return;
                case 12: // 13: end of main
                    pc = 13;
                    if (!ctx.leave(MAIN)) return;
                case 13: // after main
                    pc = 14;
                    if (!ctx.endOfSequence(MAIN.sequence())) return;
                case 14:
                    ctx.finish();
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
