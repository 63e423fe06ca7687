package masl.runtime.examples;

import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.testing.TestAgent;

/**
 * E7 of examples.md, translated by hand:
 * <pre>
 * 3 asynchronous entry main (true) {
 * 4   local int rounds = 0;
 * 5   asynchronous entry work (rounds < .getProxyID() + 1) {
 * 6     rounds++;
 * 7     reelect;
 * 8   }
 * 9   .logln(.getProxyID() + ":" + rounds);
 * 10 }
 * </pre>
 * Kept by hand as a worked example of the generated-code contract: {@link HandTranslationTest}
 * holds it equal to what the translator makes of examples.md.
 */
final class E7Reelect extends AgentProgram {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final EntryDefinition WORK = MAIN.child("work", Mode.ASYNCHRONOUS);

    private final TestAgent self;
    private int main$rounds;

    E7Reelect(TestAgent self) {
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
                        case SKIPPED -> { pc = 9; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 1: // 4: local int rounds = 0;
                    main$rounds = 0;
                case 2: // 5: asynchronous entry work (rounds < .getProxyID() + 1)
                    pc = 3;
                    switch (ctx.enter(WORK, main$rounds < self.getProxyID() + 1)) {
                        case SKIPPED -> { pc = 6; continue; }
                        case WAITING -> { return; }
                        case ENTERED -> { }
                    }
                case 3: // 6: rounds++;
                    main$rounds++;
                    pc = 4;
                    if (!ctx.stepBoundary()) return;
                case 4: // 7: reelect;  (work declares no locals: nothing to keep)
                    ctx.reelect(WORK);
                    pc = 2;
                    continue;
                case 5: // 8: end of work
                    pc = 6;
                    if (!ctx.leave(WORK)) return;
                case 6: // 8: end of the e-sequence {work}
                    pc = 7;
                    if (!ctx.endOfSequence(WORK.sequence())) return;
                case 7: // 9: .logln(.getProxyID() + ":" + rounds);
                    self.logln(self.getProxyID() + ":" + main$rounds);
                    pc = 8;
                    if (!ctx.stepBoundary()) return;
                case 8: // 10: end of main
                    pc = 9;
                    if (!ctx.leave(MAIN)) return;
                case 9: // after main
                    pc = 10;
                    if (!ctx.endOfSequence(MAIN.sequence())) return;
                case 10:
                    ctx.finish();
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
