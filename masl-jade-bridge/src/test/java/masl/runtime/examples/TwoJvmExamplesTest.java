package masl.runtime.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import masl.jade.BodyContainerMain;
import masl.jade.JadeLauncher;
import masl.jade.TestPrograms;
import masl.jade.platform.PlatformContainers;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.MissionOutcome;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.testing.jade.JadePlatformExtension;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The hand-translated E2, E4 and E6 with their agents split across two containers in two JVMs:
 * this JVM's main container runs the mission (the coordinator), a second JVM
 * ({@link BodyContainerMain}) hosts the bodies of some agents. Journals as in-process; the second
 * JVM's container has left the platform when the mission's end returns.
 */
@Timeout(120)
@Tag("slow")
class TwoJvmExamplesTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(60);

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void e2WithTwoOfFiveAgentsInAnotherJvm() throws Exception {
        Split run = split(E2SharedAndLocal.MAIN, 5, E2SharedAndLocal::new, Map.of("a1", "c2", "a3", "c2"));
        assertEquals(inProcess(E2SharedAndLocal.MAIN, 5, E2SharedAndLocal::new), run.journal());
        assertTrue(run.containerOutput().contains("hosted a1, a3\n"), run.containerOutput());
    }

    /** The leader and one worker away: the event reaches them as INFORMs; the journal as in-process. */
    @Test
    void e4WithTheLeaderAndAWorkerInAnotherJvm() throws Exception {
        Split run = split(E4Events.MAIN, 4, E4Events::new, Map.of("a0", "c2", "a2", "c2"));
        assertEquals(sortedLines(inProcess(E4Events.MAIN, 4, E4Events::new)), sortedLines(run.journal()));
        assertTrue(run.journal().startsWith("heard now\n"), run.journal());
        assertTrue(run.containerOutput().contains(
                "event {\"event\":\"go\",\"block\":\"main\",\"emitter\":\"a0\",\"message\":\"now\"}\n"),
                run.containerOutput());
    }

    @Test
    void e6WithTheKeeperAndAPassengerInAnotherJvm() throws Exception {
        Split run = split(E6OneAtATime.MAIN, 4, E6OneAtATime::new, Map.of("a0", "c2", "a3", "c2"));
        assertEquals(inProcess(E6OneAtATime.MAIN, 4, E6OneAtATime::new), run.journal());
    }

    private record Split(String journal, String containerOutput) {
    }

    private static String sortedLines(String journal) {
        return String.join("\n", journal.lines().sorted().toList());
    }

    private static String inProcess(EntryDefinition main, int agents, Function<TestAgent, AgentProgram> program) {
        return Missions.run(Driver.THREADS, main, agents, program).journal();
    }

    private static Split split(EntryDefinition main, int agents, Function<TestAgent, AgentProgram> program,
            Map<String, String> placement) throws Exception {
        try (SecondJvm container = BodyContainerMain.start(JADE.platform(), "c2")) {
            MissionOutcome outcome = JadeLauncher.of(TestPrograms.of(main, agents, program))
                    .types(TestPrograms::type).place(placement).secret(BodyContainerMain.SECRET)
                    .run(JADE.platform(), TIMEOUT);
            assertTrue(outcome.completed(), outcome + "\n" + container.output());
            // Else the platform's shutdown could meet it half-gone, and JADE print a stack trace.
            assertEquals(List.of(JADE.platform().containerName()), PlatformContainers.of(JADE.platform()),
                    "the containers left the platform before the mission's end returned");
            return new Split(outcome.journal(), container.assertEndsByItself());
        }
    }
}
