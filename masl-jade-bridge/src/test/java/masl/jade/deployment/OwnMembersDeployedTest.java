package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.Set;
import masl.jade.TestPrograms;
import masl.runtime.AgentContext;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A deployed agent's calls of its own primitives run in its container, with no message to the
 * mission, while its own permeability state filters them as in-process.
 */
@Timeout(60)
class OwnMembersDeployedTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    private static final int STEPS = 3;

    @Test
    void tenOwnPrimitivesPerStepCostNoMessage() throws Exception {
        InMemoryDeployment.Run none = deployed(0);
        InMemoryDeployment.Run ten = deployed(10);
        assertTrue(none.outcome().completed(), none.outcome().toString());
        assertTrue(ten.outcome().completed(), ten.outcome().toString());
        assertEquals("x\n".repeat(10 * STEPS), ten.outcome().journal());
        assertEquals(none.messagesFromContainer(), ten.messagesFromContainer());
    }

    @Test
    void anOwnPrimitiveIsDeniedInTheStateTheAgentSetAndAllowedInTheNext() throws Exception {
        for (Set<String> deployed : List.of(Set.<String>of(), Set.of("a0"))) {
            InMemoryDeployment.Run run = InMemoryDeployment.run(() -> TestPrograms.of(MAIN, 1, ClosesAndOpens::new),
                    deployed, TIMEOUT);
            assertTrue(run.outcome().completed(), run.outcome().toString());
            assertEquals("yes\n", run.outcome().journal(), "deployed: " + deployed);
        }
    }

    private static InMemoryDeployment.Run deployed(int callsPerStep) throws InterruptedException {
        return InMemoryDeployment.run(() -> TestPrograms.of(MAIN, 1, self -> new OwnCalls(self, callsPerStep)),
                Set.of("a0"), TIMEOUT);
    }

    /** {@code main { body }}, the body repeated while it says so, each time followed by a step boundary. */
    private abstract static class InMain extends CompactProgram {
        InMain(TestAgent self) {
            super(self);
        }

        /** The body's instructions; whether it runs once more. */
        abstract boolean body(AgentContext ctx);

        void logln(AgentContext ctx, String line) {
            ctx.invokeSelf("logln", null, () -> {
                self.logln(line);
                return null;
            });
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 3)) return;
                        continue;
                    case 1:
                        if (!step(ctx, body(ctx) ? 1 : 2)) return;
                        continue;
                    case 2:
                        if (!leave(ctx, MAIN, 3)) return;
                        continue;
                    case 3:
                        pc = 4;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 4:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /** {@code main { repeat STEPS times: callsPerStep times .logln("x"); }}. */
    private static final class OwnCalls extends InMain {
        private final int callsPerStep;
        private int steps;

        OwnCalls(TestAgent self, int callsPerStep) {
            super(self);
            this.callsPerStep = callsPerStep;
        }

        @Override
        boolean body(AgentContext ctx) {
            for (int call = 0; call < callsPerStep; call++) {
                logln(ctx, "x");
            }
            return ++steps < STEPS;
        }
    }

    /** {@code main { setAcceptState("nothing"); .logln("no"); setAcceptState("default"); .logln("yes"); }}. */
    private static final class ClosesAndOpens extends InMain {
        ClosesAndOpens(TestAgent self) {
            super(self);
        }

        @Override
        boolean body(AgentContext ctx) {
            ctx.setAcceptState("nothing");
            logln(ctx, "no");
            ctx.setAcceptState("default");
            logln(ctx, "yes");
            return false;
        }
    }
}
