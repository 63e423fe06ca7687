package masl.runtime.examples;

import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.testing.TestAgent;

/**
 * E3 of examples.md, translated by hand:
 * <pre>
 * 3 synchronous entry main (true) {
 * 4   asynchronous entry evens (.getProxyID() % 2 == 0) {
 * 5     .log("x"); .log("x"); .log("x");
 * 6   }
 * 7   .log("y");
 * 8   scalar entry end (true) { .log("\n"); }
 * 9 }
 * </pre>
 * Kept by hand as a worked example of the generated-code contract: {@link HandTranslationTest}
 * holds it equal to what the translator makes of examples.md.
 */
final class E3AsynchronousChild extends AgentProgram {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    static final ESequence EVENS_SEQUENCE = MAIN.newSequence();
    static final EntryDefinition EVENS = EVENS_SEQUENCE.block("evens", Mode.ASYNCHRONOUS);
    static final ESequence END_SEQUENCE = MAIN.newSequence();
    static final EntryDefinition END = END_SEQUENCE.block("end", Mode.SCALAR);

    private final TestAgent self;

    E3AsynchronousChild(TestAgent self) {
        this.self = self;
    }

    @Override
    @SuppressWarnings("fallthrough") // resumption points fall through into the next one
    protected void resume(AgentContext ctx) {
        while (true) {
            switch (pc) {
                case 0: // 3: synchronous entry main (true)
                    pc = 1;
                    switch (ctx.enter(MAIN, true)) {
                        case SKIPPED -> { pc = 15; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 1: // 4: asynchronous entry evens (.getProxyID() % 2 == 0)
                    pc = 2;
                    switch (ctx.enter(EVENS, self.getProxyID() % 2 == 0)) {
                        case SKIPPED -> { pc = 6; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 2: // 5: .log("x");
                    self.log("x");
                    pc = 3;
                    if (!ctx.stepBoundary()) return;
                case 3: // 5: .log("x");
                    self.log("x");
                    pc = 4;
                    if (!ctx.stepBoundary()) return;
                case 4: // 5: .log("x");
                    self.log("x");
                    pc = 5;
                    if (!ctx.stepBoundary()) return;
                case 5: // 6: end of evens
                    pc = 6;
                    if (!ctx.leave(EVENS)) return;
                case 6: // 6: end of evens, one instruction of main
                    pc = 7;
                    if (!ctx.endOfChild(EVENS)) return;
                case 7: // 6: end of the e-sequence {evens}
                    pc = 8;
                    if (!ctx.endOfSequence(EVENS_SEQUENCE)) return;
                case 8: // 7: .log("y");
                    self.log("y");
                    pc = 9;
                    if (!ctx.stepBoundary()) return;
                case 9: // 8: scalar entry end (true)
                    pc = 10;
                    switch (ctx.enter(END, true)) {
                        case SKIPPED -> { pc = 12; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 10: // 8: .log("\n");
                    self.log("\n");
                    pc = 11;
                    if (!ctx.stepBoundary()) return;
                case 11: // 8: end of end
                    pc = 12;
                    if (!ctx.leave(END)) return;
                case 12: // 8: end of end, one instruction of main
                    pc = 13;
                    if (!ctx.endOfChild(END)) return;
                case 13: // 8: end of the e-sequence {end}
                    pc = 14;
                    if (!ctx.endOfSequence(END_SEQUENCE)) return;
                case 14: // 9: end of main
                    pc = 15;
                    if (!ctx.leave(MAIN)) return;
                case 15: // after main
                    pc = 16;
                    if (!ctx.endOfSequence(MAIN.sequence())) return;
                case 16:
                    ctx.finish();
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
