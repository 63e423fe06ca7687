package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.jade.TestPrograms;
import masl.runtime.AgentContext;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@code getAcceptState(b)} in a deployed program names b's state, which the mission keeps, not the
 * caller's own: as in-process, whichever of the two is deployed.
 */
@Timeout(60)
class OthersStateDeployedTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);

    @Test
    void aDeployedAgentReadsTheStateAnotherAgentSet() throws Exception {
        for (Set<String> deployed : List.of(Set.<String>of(), Set.of("a0"), Set.of("a0", "a1"))) {
            InMemoryDeployment.Run run = InMemoryDeployment.run(() -> {
                // Each side has its own objects of both agents (the container, stand-ins of those not
                // deployed there, which answer no primitive), made in proxy id order, a team at a time.
                AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(2);
                AtomicInteger made = new AtomicInteger();
                return TestPrograms.of(MAIN, 2, self -> {
                    population.set(made.getAndIncrement() % 2, self);
                    return new ReadsTheOthersState(self, population);
                });
            }, deployed, TIMEOUT);
            assertTrue(run.outcome().completed(), run.outcome().toString());
            assertEquals("a1 is in nothing, a0 in default\n", run.outcome().journal(), "deployed: " + deployed);
        }
    }

    /**
     * {@code synchronous entry main { if (me == 1) setAcceptState("nothing"); | if (me == 0)
     * .logln("a1 is in " + getAcceptState(a1) + ", a0 in " + getAcceptState()); }}: a1 closes itself
     * before the barrier, a0 reads after it.
     */
    private static final class ReadsTheOthersState extends CompactProgram {
        private final AtomicReferenceArray<TestAgent> population;

        ReadsTheOthersState(TestAgent self, AtomicReferenceArray<TestAgent> population) {
            super(self);
            this.population = population;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 4)) return;
                        continue;
                    case 1:
                        if (self == population.get(1)) {
                            ctx.setAcceptState("nothing");
                        }
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2:
                        if (self == population.get(0)) {
                            String line = "a1 is in " + ctx.getAcceptState(population.get(1)) + ", a0 in "
                                    + ctx.getAcceptState();
                            ctx.invokeSelf("logln", null, () -> {
                                self.logln(line);
                                return null;
                            });
                        }
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3:
                        if (!leave(ctx, MAIN, 4)) return;
                        continue;
                    case 4:
                        pc = 5;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 5:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }
}
