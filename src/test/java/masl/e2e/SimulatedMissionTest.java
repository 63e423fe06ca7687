package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.AgentPath;
import masl.sim.output.RunRecorder;
import masl.sim.scenario.RunOptions;
import masl.sim.scenario.Scenario;
import masl.sim.scenario.ScenarioLoader;
import masl.sim.scenario.ScenarioRunner;
import masl.sim.scenario.SimulationResult;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A MASL program, translated and compiled as {@code masl run} does, runs on simulated robots:
 * what {@code masl run --sim} will do with {@link ScenarioRunner}.
 */
class SimulatedMissionTest {

    /** Two wheeled robots wander in lock-step rounds for two simulated seconds, avoiding what is ahead. */
    private static final String PROGRAM = """
            import WheeledRobot.xml as WheeledRobot;
            WheeledRobot k0, k1 = newAgent(WheeledRobot);
            synchronous entry main (true) {
              local int round = 0;
              while (round < 40) {
                if (.getProximity(2) < 0.06 || .getProximity(3) < 0.06) {
                  .setSpeeds(-3.0, 3.0);
                } else {
                  .setSpeeds(5.0, 5.0);
                }
                .sleep(50);
                round++;
              }
              .stop();
              scalar entry report (true) { .logln("done at " + round); }
            }
            """;

    private static final String ARENA = """
            <xode version="1.0r23"><world><space>
              <geom name="floor"><plane a="0" b="0" c="1" d="0"/></geom>
              <geom name="wall"><transform><position x="0.5" y="0" z="0.05"/></transform>
                <box sizex="0.1" sizey="2" sizez="0.1"/></geom>
            </space></world></xode>""";

    @TempDir
    Path folder;

    @Test
    void aTranslatedMissionDrivesSimulatedRobotsTheSameWayTwice() throws Exception {
        Files.writeString(folder.resolve("arena.xode"), ARENA);
        Path file = Files.writeString(folder.resolve("wander.scenario.xml"), """
                <scenario name="wander">
                  <physics seed="5"/>
                  <world file="arena.xode"/>
                  <agent name="k0" model="wheeled"><pose x="0.2" y="0" heading="0"/></agent>
                  <agent name="k1" model="wheeled"><pose x="-0.3" y="0.3" heading="90"/></agent>
                  <mission file="wander.masl"/>
                </scenario>""");
        Scenario scenario = new ScenarioLoader().load(file);
        AgentPath agentPath = AgentPath.parse("");
        Translation translation = new Translator(agentPath).translate(SourceFile.of("wander.masl", PROGRAM));
        assertTrue(translation.succeeded(), () -> translation.diagnostics().toString());
        MissionLoader loaded = MissionLoader.load(translation, agentPath);

        RunOptions options = RunOptions.defaults().withTimeout(Duration.ofMinutes(1));
        SimulationResult first = new ScenarioRunner(scenario).run(loaded.program(), options);
        SimulationResult second = new ScenarioRunner(scenario).run(loaded.program(), options);

        assertEquals(MissionOutcome.Status.COMPLETED, first.outcome().status(), first.outcome()::toString);
        assertEquals("done at 40\n", first.outcome().journal());
        assertEquals(2.0, first.simulatedSeconds(), 0.05, "40 rounds of 50 ms in lock-step");
        List<RunRecorder.Sample> k1 = first.recorder().trajectory("k1");
        assertTrue(k1.get(k1.size() - 1).y() - k1.get(0).y() > 0.1, "k1 drove north");
        List<RunRecorder.Sample> k0 = first.recorder().trajectory("k0");
        assertTrue(k0.stream().allMatch(s -> s.x() < 0.45 - 0.04), "k0 turned before the wall");
        assertEquals(first.trajectoriesCsv(), second.trajectoriesCsv(), "lock-step runs repeat");
        assertEquals(first.trace(), second.trace());
    }
}
