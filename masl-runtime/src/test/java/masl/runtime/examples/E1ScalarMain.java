package masl.runtime.examples;

import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.testing.TestAgent;

/**
 * E1 of examples.md, translated by hand as the translator would:
 * <pre>
 * 3 scalar entry main (true) {
 * 4   .log("Hi ");
 * 5   .logln("team");
 * 6 }
 * </pre>
 * Kept by hand as a worked example of the generated-code contract: {@link HandTranslationTest}
 * holds it equal to what the translator makes of examples.md.
 */
final class E1ScalarMain extends AgentProgram {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SCALAR);

    private final TestAgent self;

    E1ScalarMain(TestAgent self) {
        this.self = self;
    }

    @Override
    @SuppressWarnings("fallthrough") // resumption points fall through into the next one
    protected void resume(AgentContext ctx) {
        while (true) {
            switch (pc) {
                case 0: // 3: scalar entry main (true)
                    pc = 1;
                    switch (ctx.enter(MAIN, true)) {
                        case SKIPPED -> { pc = 4; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 1: // 4: .log("Hi ");
                    self.log("Hi ");
                    pc = 2;
                    if (!ctx.stepBoundary()) return;
                case 2: // 5: .logln("team");
                    self.logln("team");
                    pc = 3;
                    if (!ctx.stepBoundary()) return;
                case 3: // 6: end of main
                    pc = 4;
                    if (!ctx.leave(MAIN)) return;
                case 4: // after main
                    pc = 5;
                    if (!ctx.endOfSequence(MAIN.sequence())) return;
                case 5:
                    ctx.finish();
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
