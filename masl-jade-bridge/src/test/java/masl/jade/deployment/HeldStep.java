package masl.jade.deployment;

import java.util.function.Consumer;
import masl.runtime.AgentContext;
import masl.runtime.EntryDefinition;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;

/**
 * {@code synchronous entry main (true) { steps trivial instructions; .logln("done"); }}, the agent
 * running {@code hold} in its step {@code held}, or after {@code finish} if {@code held} is greater
 * than {@code steps}: where a test keeps steps in their container (in a primitive that blocks, as
 * robots' do, or as a slow link delays the end of a step) while it looks at the threads.
 */
final class HeldStep extends CompactProgram {
    private final EntryDefinition main;
    private final int steps;
    private final int held;
    private final Consumer<TestAgent> hold;
    private int step;

    HeldStep(TestAgent self, EntryDefinition main, int steps, int held, Consumer<TestAgent> hold) {
        super(self);
        this.main = main;
        this.steps = steps;
        this.held = held;
        this.hold = hold;
    }

    @Override
    protected void resume(AgentContext ctx) {
        while (true) {
            switch (pc) {
                case 0:
                    if (!arrive(ctx, main, true, 1, 3)) return;
                    continue;
                case 1:
                    if (++step == held) {
                        hold.accept(self);
                    }
                    if (!step(ctx, step < steps ? 1 : 2)) return;
                    continue;
                case 2:
                    self.logln("done");
                    if (!leave(ctx, main, 3)) return;
                    continue;
                case 3:
                    pc = 4;
                    if (!ctx.endOfSequence(main.sequence())) return;
                    continue;
                case 4:
                    ctx.finish();
                    if (held > steps) {
                        hold.accept(self);
                    }
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }
}
