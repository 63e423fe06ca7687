package masl.runtime.examples;

import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.SharedDeclaration;
import masl.runtime.testing.TestAgent;

/**
 * E2 of examples.md, translated by hand (the worked example of docs/generated-code-contract.md):
 * <pre>
 *  3 synchronous entry main (true) {
 *  4   shared int n = 0;
 *  5   local int mine = 0;
 *  6   n++;
 *  7   mine++;
 *  8   scalar entry report (true) { .logln("n=" + n); }
 *  9   .logln("mine=" + mine);
 * 10 }
 * </pre>
 * Kept by hand as a worked example of the generated-code contract: {@link HandTranslationTest}
 * holds it equal to what the translator makes of examples.md.
 */
final class E2SharedAndLocal extends AgentProgram {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    static final SharedDeclaration<Integer> MAIN_N = MAIN.declareShared("n", 0);
    static final ESequence REPORT_SEQUENCE = MAIN.newSequence();
    static final EntryDefinition REPORT = REPORT_SEQUENCE.block("report", Mode.SCALAR);

    private final TestAgent self;
    private int main$mine;

    E2SharedAndLocal(TestAgent self) {
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
                        case SKIPPED -> { pc = 10; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 1: // 4-5: declarations (zero duration)
                    ctx.shared(MAIN_N).initialise(() -> 0);
                    main$mine = 0;
                    // 6: n++;
                    ctx.shared(MAIN_N).getAndUpdate(n -> n + 1);
                    pc = 2;
                    if (!ctx.stepBoundary()) return;
                case 2: // 7: mine++;
                    main$mine++;
                    pc = 3;
                    if (!ctx.stepBoundary()) return;
                case 3: // 8: scalar entry report (true)
                    pc = 4;
                    switch (ctx.enter(REPORT, true)) {
                        case SKIPPED -> { pc = 6; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 4: // 8: .logln("n=" + n);
                    self.logln("n=" + ctx.shared(MAIN_N).get());
                    pc = 5;
                    if (!ctx.stepBoundary()) return;
                case 5: // 8: end of report
                    pc = 6;
                    if (!ctx.leave(REPORT)) return;
                case 6: // 8: end of report, one instruction of main
                    pc = 7;
                    if (!ctx.endOfChild(REPORT)) return;
                case 7: // 8: end of the e-sequence {report}
                    pc = 8;
                    if (!ctx.endOfSequence(REPORT_SEQUENCE)) return;
                case 8: // 9: .logln("mine=" + mine);
                    self.logln("mine=" + main$mine);
                    pc = 9;
                    if (!ctx.stepBoundary()) return;
                case 9: // 10: end of main
                    pc = 10;
                    if (!ctx.leave(MAIN)) return;
                case 10: // after main
                    pc = 11;
                    if (!ctx.endOfSequence(MAIN.sequence())) return;
                case 11:
                    ctx.finish();
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
