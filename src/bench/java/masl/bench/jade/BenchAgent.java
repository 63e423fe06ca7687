package masl.bench.jade;

import java.util.concurrent.CompletableFuture;
import masl.runtime.AgentContext;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;

/**
 * The MASL agent the bridge benchmark invokes: a primitive {@code nop} that does nothing, and a
 * program that waits (holding no CPU) until the benchmark releases it, serving invocations
 * meanwhile as a blocked MASL agent does (§5).
 */
public final class BenchAgent extends AgentImplementation {

    private final CompletableFuture<Void> released = new CompletableFuture<>();

    public void nop() {
        // The invocation's round trip is what is measured.
    }

    /** Lets the agent's program finish. */
    void release() {
        released.complete(null);
    }

    /** Awaits the release, then finishes: no main block, nothing else. */
    static final class Program extends AgentProgram {
        private final BenchAgent self;

        Program(BenchAgent self) {
            this.self = self;
        }

        @Override
        protected void resume(AgentContext ctx) {
            if (pc == 0) {
                pc = 1;
                if (!ctx.await(self.released)) {
                    return;
                }
            }
            ctx.finish();
        }
    }
}
