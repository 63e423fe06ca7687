package masl.runtime.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicReferenceArray;
import java.util.function.Function;
import java.util.function.Supplier;
import masl.jade.TestPrograms;
import masl.jade.deployment.InMemoryDeployment;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.MissionProgram;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The hand-translated examples with their programs deployed to a container (in this JVM, joined to
 * the mission by wires that carry JSON text): each agent's program runs there against a remote
 * context, the mission here decides; the journals are those examples.md states, as in-process.
 */
@Timeout(120)
class DeployedExamplesTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);
    private static final int RUNS = 10;

    @Test
    void e1ScalarMain() throws Exception {
        for (int run = 0; run < RUNS; run++) {
            assertEquals("Hi team\n", deployed(E1ScalarMain.MAIN, 3, E1ScalarMain::new, "a0", "a1", "a2"));
        }
    }

    @Test
    void e2SharedAndLocalInLockStepWithThreeOfFiveDeployed() throws Exception {
        for (int run = 0; run < RUNS; run++) {
            assertEquals("n=5\n" + "mine=1\n".repeat(5),
                    deployed(E2SharedAndLocal.MAIN, 5, E2SharedAndLocal::new, "a0", "a2", "a4"));
        }
    }

    @Test
    void e3AsynchronousChild() throws Exception {
        for (int run = 0; run < RUNS; run++) {
            assertEquals("xxxxxxyyyy\n",
                    deployed(E3AsynchronousChild.MAIN, 4, E3AsynchronousChild::new, "a0", "a1", "a2", "a3"));
        }
    }

    @Test
    void e4EventsWithTheLeaderAndOneWorkerDeployed() throws Exception {
        for (int run = 0; run < RUNS; run++) {
            String journal = deployed(E4Events.MAIN, 4, E4Events::new, "a0", "a2");
            assertEquals(List.of("heard now", "heard now", "heard now", "heard now", "worker 1", "worker 2",
                    "worker 3"), sortedLines(journal), journal);
            assertTrue(journal.startsWith("heard now\n"), journal);
        }
    }

    @Test
    void e5DeniedInvocationBecomesTimeout() throws Exception {
        for (int run = 0; run < RUNS; run++) {
            assertEquals("timeout\nseen=0\n", deployed(E5Permeability.MAIN, 2,
                    () -> {
                        AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(2);
                        return self -> new E5Permeability(self, population);
                    }, "a0", "a1"));
        }
    }

    @Test
    void e6OneAtATimeWithTheKeeperDeployed() throws Exception {
        for (int run = 0; run < RUNS; run++) {
            assertEquals("in 1\nin 1\nin 1\n", deployed(E6OneAtATime.MAIN, 4, E6OneAtATime::new, "a0", "a3"));
        }
    }

    @Test
    void e7Reelect() throws Exception {
        for (int run = 0; run < RUNS; run++) {
            assertEquals(List.of("0:1", "1:2", "2:3"),
                    sortedLines(deployed(E7Reelect.MAIN, 3, E7Reelect::new, "a0", "a1", "a2")));
        }
    }

    @Test
    void e8BreakOutOfTwo() throws Exception {
        for (int run = 0; run < RUNS; run++) {
            String journal = deployed(E8BreakOutOfTwo.MAIN, 2, E8BreakOutOfTwo::new, "a1");
            assertEquals(List.of("in", "in", "out", "out"), sortedLines(journal));
            assertTrue(journal.startsWith("in\n"), journal);
        }
    }

    private static String deployed(EntryDefinition main, int agents, Function<TestAgent, AgentProgram> program,
            String... names) throws InterruptedException {
        return deployed(main, agents, () -> program, names);
    }

    /** {@code programs} gives each side (the mission, the container) programs of its own. */
    private static String deployed(EntryDefinition main, int agents,
            Supplier<Function<TestAgent, AgentProgram>> programs, String... names) throws InterruptedException {
        Supplier<MissionProgram> mission = () -> TestPrograms.of(main, agents, programs.get());
        InMemoryDeployment.Run run = InMemoryDeployment.run(mission, Set.of(names), TIMEOUT);
        assertTrue(run.outcome().completed(), run.outcome().toString());
        // At least a step of each deployed agent's: the programs ran in the container.
        assertTrue(run.messagesFromContainer() >= names.length, run.messagesFromContainer() + " messages");
        return run.outcome().journal();
    }

    private static List<String> sortedLines(String journal) {
        List<String> lines = new ArrayList<>(journal.lines().toList());
        lines.sort(null);
        return lines;
    }
}
