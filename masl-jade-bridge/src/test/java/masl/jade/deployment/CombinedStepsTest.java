package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.jade.TestPrograms;
import masl.runtime.AgentContext;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A container's agents in lock-step cost a few messages per step, not a few per agent: their
 * arrivals at the barrier go to the mission together, and the trip's wake-ups come back together.
 */
@Timeout(60)
class CombinedStepsTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    private static final int AGENTS = 6;
    private static final int STEPS = 40;

    @Test
    void aContainersAgentsArriveAndAreWokenTogether() throws Exception {
        Set<String> all = IntStream.range(0, AGENTS).mapToObj(i -> "a" + i).collect(Collectors.toSet());
        InMemoryDeployment.Run run = InMemoryDeployment.run(() -> TestPrograms.of(MAIN, AGENTS, LockStep::new), all,
                TIMEOUT);
        assertTrue(run.outcome().completed(), run.outcome().toString());
        assertEquals("done\n".repeat(AGENTS), run.outcome().journal());
        // One message each way per step, and a few to enter and leave; an agent's own messages would be
        // at least its arrival and its wake-up each step: 2 * AGENTS per step each way.
        assertTrue(run.messagesFromContainer() < 2 * STEPS, run.messagesFromContainer() + " messages from the container");
        assertTrue(run.messagesToContainer() < 2 * STEPS, run.messagesToContainer() + " messages to the container");
    }

    /** {@code synchronous entry main (true) { STEPS trivial instructions; .logln("done"); }}. */
    private static final class LockStep extends CompactProgram {
        private int steps;

        LockStep(TestAgent self) {
            super(self);
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 3)) return;
                        continue;
                    case 1:
                        if (!step(ctx, ++steps < STEPS ? 1 : 2)) return;
                        continue;
                    case 2:
                        self.logln("done");
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
}
