package masl.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicReference;
import java.util.stream.IntStream;
import javax.imageio.ImageIO;
import masl.agents.Default;
import masl.agents.MaamAtom;
import masl.agents.WheeledRobot;
import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.MissionOutcome;
import masl.runtime.diagnostic.Diagnostic;
import masl.sim.output.RunRecorder;
import masl.sim.output.TrajectoryPicture;
import masl.sim.robots.SimulatedWheeledRobot;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Scenarios run missions with robots bound to bodies, on simulated time, reproducibly in lock-step. */
class ScenarioRunnerTest {

    /** The ground and four walls around a 1.2 m square centred on the origin. */
    static final String ARENA = """
            <xode version="1.0r23"><world><space>
              <geom name="floor"><plane a="0" b="0" c="1" d="0"/></geom>
              <geom name="north"><transform><position x="0" y="0.65" z="0.05"/></transform><box sizex="1.4" sizey="0.1" sizez="0.1"/></geom>
              <geom name="south"><transform><position x="0" y="-0.65" z="0.05"/></transform><box sizex="1.4" sizey="0.1" sizez="0.1"/></geom>
              <geom name="east"><transform><position x="0.65" y="0" z="0.05"/></transform><box sizex="0.1" sizey="1.2" sizez="0.1"/></geom>
              <geom name="west"><transform><position x="-0.65" y="0" z="0.05"/></transform><box sizex="0.1" sizey="1.2" sizez="0.1"/></geom>
            </space></world></xode>""";

    @TempDir
    Path folder;

    private Scenario scenario(String body) throws IOException, ScenarioException {
        Files.writeString(folder.resolve("arena.xode"), ARENA);
        return new ScenarioLoader().load("test.scenario.xml", "<scenario name=\"test\">\n<world file=\"arena.xode\"/>\n"
                + body + "\n</scenario>", folder);
    }

    private static RunOptions quick() {
        return RunOptions.defaults().withTimeout(Duration.ofMinutes(1));
    }

    @Test
    void aRobotDrivesForItsSimulatedSleepAndReportsOdometry() throws Exception {
        Scenario scenario = scenario("""
                <physics seed="1"/>
                <agent name="k0" model="wheeled"><pose x="-0.4" y="0.2" heading="0"/></agent>""");
        TestMission mission = new TestMission().agent("k0", WheeledRobot.class, impl -> RobotPrograms.driveThenStop(impl, 4, 4, 2000));
        SimulationResult result = new ScenarioRunner(scenario).run(mission, quick());
        assertEquals(MissionOutcome.Status.COMPLETED, result.outcome().status(), result.outcome()::toString);
        assertEquals(2.0, result.simulatedSeconds(), 0.02, "the run lasted the robot's sleep");
        List<RunRecorder.Sample> path = result.recorder().trajectory("k0");
        double travelled = path.get(path.size() - 1).x() - path.get(0).x();
        double expected = 4 * 0.021 * 2;
        assertEquals(expected, travelled, 0.1 * expected);
        assertTrue(result.outcome().journal().startsWith("0 at -0.2"), result.outcome().journal());
    }

    @Test
    void twoLockStepRunsWithTheSameSeedGiveByteIdenticalOutput() throws Exception {
        Scenario scenario = scenario("""
                <physics seed="7" slicesPerStep="4"/>
                <agent name="k0" model="wheeled"><pose x="-0.4" y="-0.3" heading="30"/></agent>
                <agent name="k1" model="wheeled"><pose x="0.3" y="0.1" heading="200"/></agent>
                <agent name="k2" model="wheeled"><pose x="0" y="0.45" heading="-60"/></agent>
                <fault agent="k2" time="2.5"/>""");
        TestMission mission = new TestMission()
                .agent("k0", WheeledRobot.class, impl -> RobotPrograms.wanderInStep(impl, 80))
                .agent("k1", WheeledRobot.class, impl -> RobotPrograms.wanderInStep(impl, 80))
                .agent("k2", WheeledRobot.class, impl -> RobotPrograms.wanderInStep(impl, 80))
                .main(RobotPrograms.TOGETHER);
        Path first = folder.resolve("first");
        Path second = folder.resolve("second");
        SimulationResult a = new ScenarioRunner(scenario).run(mission, quick().withOutput(first));
        SimulationResult b = new ScenarioRunner(scenario).run(mission, quick().withOutput(second));
        assertEquals(MissionOutcome.Status.COMPLETED, a.outcome().status(), a.outcome()::toString);
        assertTrue(a.recorder().samples().size() > 100, "a trace worth comparing");
        assertTrue(a.eventsJsonLines().contains("\"agent\":\"k2\",\"event\":\"fault\""), a.eventsJsonLines());
        assertTrue(a.trace().lines().filter(line -> line.contains("barrier-tripped")).count() >= 80, "rounds in step");
        assertEquals(12, a.outcome().journal().lines().count(), a.outcome().journal());
        for (String file : List.of(ScenarioRunner.TRAJECTORIES, ScenarioRunner.EVENTS, ScenarioRunner.TRACE,
                ScenarioRunner.JOURNAL, ScenarioRunner.PICTURE)) {
            assertEquals(-1L, Files.mismatch(first.resolve(file), second.resolve(file)), file + " differs");
        }
    }

    @Test
    void aDifferentSeedRunsTheSameMissionToTheEnd() throws Exception {
        String agents = """
                <agent name="k0" model="wheeled"><pose x="-0.4" y="-0.3" heading="30"/></agent>
                <agent name="k1" model="wheeled"><pose x="0.3" y="0.1" heading="200"/></agent>""";
        TestMission mission = new TestMission()
                .agent("k0", WheeledRobot.class, impl -> RobotPrograms.wander(impl, 40))
                .agent("k1", WheeledRobot.class, impl -> RobotPrograms.wander(impl, 40));
        SimulationResult a = new ScenarioRunner(scenario("<physics seed=\"1\"/>" + agents)).run(mission, quick());
        SimulationResult b = new ScenarioRunner(scenario("<physics seed=\"2\"/>" + agents)).run(mission, quick());
        assertEquals(MissionOutcome.Status.COMPLETED, b.outcome().status());
        assertEquals(a.recorder().samples().size(), b.recorder().samples().size());
    }

    @Test
    void aFaultStopsTheRobotAndIsAnEvent() throws Exception {
        Scenario scenario = scenario("""
                <agent name="k0" model="wheeled"><pose x="-0.4" y="0" heading="0"/></agent>
                <fault agent="k0" time="1"/>""");
        TestMission mission = new TestMission().agent("k0", WheeledRobot.class, impl -> RobotPrograms.driveThenStop(impl, 4, 4, 3000));
        SimulationResult result = new ScenarioRunner(scenario).run(mission, quick());
        List<RunRecorder.Sample> path = result.recorder().trajectory("k0");
        double atFault = path.stream().filter(s -> s.time() >= 1.2).findFirst().orElseThrow().x();
        assertEquals(atFault, path.get(path.size() - 1).x(), 0.003, "no motion after the fault");
        assertEquals(List.of(new RunRecorder.Event(1.0, "k0", "fault", "motors stopped, battery 0"),
                new RunRecorder.Event(1.0, "k0", "battery-empty", "")), result.recorder().events());
    }

    @Test
    void theDurationStopsTheRunAtThatSimulatedTime() throws Exception {
        Scenario scenario = scenario("""
                <physics duration="0.5"/>
                <agent name="k0" model="wheeled"/>""");
        TestMission mission = new TestMission().agent("k0", WheeledRobot.class, impl -> RobotPrograms.driveThenStop(impl, 4, 4, 60_000));
        SimulationResult result = new ScenarioRunner(scenario).run(mission, quick());
        assertEquals(MissionOutcome.Status.STOPPED, result.outcome().status());
        assertEquals(0.5, result.simulatedSeconds(), 0.05);
    }

    @Test
    void softwareAgentsGetTheirDeclaredOrTheScenariosClass() throws Exception {
        Scenario scenario = scenario("<agent name=\"logger\" class=\"" + LoudDefault.class.getName() + "\"/>");
        TestMission mission = new TestMission()
                .agent("plain", Default.class, RobotPrograms::hello)
                .agent("logger", Default.class, RobotPrograms::hello);
        SimulationResult result = new ScenarioRunner(scenario).run(mission, quick());
        assertEquals(MissionOutcome.Status.COMPLETED, result.outcome().status());
        assertTrue(result.outcome().journal().contains("hello from Default\n"), result.outcome().journal());
        assertTrue(result.outcome().journal().contains("hello from LoudDefault\n"), result.outcome().journal());
    }

    /** A software agent class a scenario names. */
    public static final class LoudDefault extends Default {
    }

    @Test
    void theInitialisationClassRunsOnceBeforeThePrograms() throws Exception {
        Scenario scenario = scenario("""
                <agent name="k0" model="wheeled"/>
                <initialisation class="%s"/>""".formatted(DrainBattery.class.getName()));
        AtomicReference<Double> seen = new AtomicReference<>();
        TestMission mission = new TestMission().agent("k0", WheeledRobot.class, impl -> new AgentProgram() {
            @Override
            protected void resume(AgentContext ctx) {
                seen.set(((WheeledRobot) impl).getBattery());
                ctx.finish();
            }
        });
        new ScenarioRunner(scenario).run(mission, quick());
        assertEquals(0.0, seen.get());
    }

    /** Empties every wheeled robot's battery. */
    public static final class DrainBattery implements ScenarioInitialiser {
        @Override
        public void initialise(Simulation simulation) {
            simulation.robots().values().forEach(r -> r.hardware(SimulatedWheeledRobot.class).fail());
        }
    }

    @Test
    void aPlacedAgentTheMissionDoesNotDeclareIsALocatedError() throws Exception {
        Scenario scenario = scenario("<agent name=\"ghost\" model=\"wheeled\"/>");
        TestMission mission = new TestMission().agent("k0", WheeledRobot.class, RobotPrograms::hello);
        ScenarioException e = assertThrows(ScenarioException.class, () -> new ScenarioRunner(scenario).run(mission, quick()));
        assertEquals(List.of("test.scenario.xml:3:1: error: agent 'ghost' is not declared by the mission (it declares [k0])"),
                headlines(e));
    }

    @Test
    void aModelThatIsNotTheDeclaredTypeIsALocatedError() throws Exception {
        Scenario scenario = scenario("<agent name=\"a0\" model=\"wheeled\"/>");
        TestMission mission = new TestMission().agent("a0", MaamAtom.class, RobotPrograms::hello);
        ScenarioException e = assertThrows(ScenarioException.class, () -> new ScenarioRunner(scenario).run(mission, quick()));
        assertEquals(List.of("test.scenario.xml:3:1: error: agent 'a0' is declared a masl.agents.MaamAtom by the mission, "
                + "but masl.agents.WheeledRobot is not one"), headlines(e));
    }

    @Test
    void aRobotClassMustExtendItsModelsClass() throws Exception {
        Scenario scenario = scenario("<agent name=\"k0\" model=\"wheeled\" class=\"masl.agents.Default\"/>");
        TestMission mission = new TestMission().agent("k0", Default.class, RobotPrograms::hello);
        ScenarioException e = assertThrows(ScenarioException.class, () -> new ScenarioRunner(scenario).run(mission, quick()));
        assertEquals(List.of("test.scenario.xml:3:1: error: class masl.agents.Default of agent 'k0' does not extend "
                + "masl.agents.WheeledRobot, the class of model 'wheeled'"), headlines(e));
    }

    @Test
    void aSubclassOfTheModelsClassGetsTheBody() throws Exception {
        Scenario scenario = scenario("<agent name=\"k0\" model=\"wheeled\" class=\"" + CarefulRobot.class.getName() + "\"/>");
        AtomicReference<Double> battery = new AtomicReference<>();
        TestMission mission = new TestMission().agent("k0", WheeledRobot.class, impl -> new AgentProgram() {
            @Override
            protected void resume(AgentContext ctx) {
                battery.set(((CarefulRobot) impl).getBattery());
                ctx.finish();
            }
        });
        new ScenarioRunner(scenario).run(mission, quick());
        assertEquals(1.0, battery.get(), 1e-3, "a full battery read through the subclass");
    }

    private static List<String> headlines(ScenarioException e) {
        return e.diagnostics().stream().map(Diagnostic::headline).toList();
    }

    /** A user's robot class: the model's class with more of its own. */
    public static final class CarefulRobot extends WheeledRobot {
    }

    @Test
    void anInitialisationClassThatIsMissingIsALocatedError() throws Exception {
        Scenario scenario = scenario("<initialisation class=\"no.such.Setup\"/>");
        ScenarioException e = assertThrows(ScenarioException.class,
                () -> new ScenarioRunner(scenario).run(new TestMission(), quick()));
        assertEquals(List.of("test.scenario.xml:3:1: error: initialisation class: class no.such.Setup not found"), headlines(e));
    }

    @Test
    void threadedModeRunsTheSameMissionOnSimulatedTime() throws Exception {
        Scenario scenario = scenario("""
                <physics mode="threaded" realTimeFactor="0"/>
                <agent name="k0" model="wheeled"><pose x="-0.4" y="0" heading="0"/></agent>""");
        TestMission mission = new TestMission().agent("k0", WheeledRobot.class, impl -> RobotPrograms.driveThenStop(impl, 4, 4, 2000));
        SimulationResult result = new ScenarioRunner(scenario).run(mission, quick());
        assertEquals(MissionOutcome.Status.COMPLETED, result.outcome().status());
        assertTrue(result.simulatedSeconds() >= 2.0, "slept 2 simulated seconds: " + result.simulatedSeconds());
        List<RunRecorder.Sample> path = result.recorder().trajectory("k0");
        assertTrue(path.get(path.size() - 1).x() - path.get(0).x() > 0.1, "drove");
    }

    @Test
    void atomsInAScenarioLatchAndTheLatchIsAnEvent() throws Exception {
        Scenario scenario = scenario("""
                <agent name="a0" model="maam-atom"><pose x="0" y="0"/></agent>
                <agent name="a1" model="maam-atom"><pose x="0.12" y="0"/></agent>""");
        TestMission mission = new TestMission()
                .agent("a0", MaamAtom.class, impl -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        MaamAtom atom = (MaamAtom) impl;
                        if (pc == 0) {
                            pc = 1;
                            if (!ctx.sleep(300)) {
                                return;
                            }
                        }
                        if (pc == 1) {
                            atom.logln("attached " + atom.attach(MaamAtom.FRONT, 1, MaamAtom.BACK));
                            pc = 2;
                            if (!ctx.sleep(300)) {
                                return;
                            }
                        }
                        atom.detach(MaamAtom.FRONT);
                        atom.logln("attached " + atom.isAttached(MaamAtom.FRONT));
                        ctx.finish();
                    }
                })
                .agent("a1", MaamAtom.class, RobotPrograms::hello);
        SimulationResult result = new ScenarioRunner(scenario).run(mission, quick());
        assertTrue(result.outcome().journal().contains("attached true\n"), result.outcome().journal());
        assertTrue(result.outcome().journal().endsWith("attached false\n"), result.outcome().journal());
        assertEquals(List.of("0.300 a0 attach a0.frontLeg a1.backLeg", "0.600 a0 detach a0.frontLeg a1.backLeg"),
                result.recorder().events().stream()
                        .map(e -> String.format(Locale.ROOT, "%.3f %s %s %s", e.time(), e.agent(), e.kind(), e.detail()))
                        .toList());
    }

    @Test
    void aScenarioFileWithItsWorldNextToItRunsFromItsPath() throws Exception {
        Path file = Path.of(getClass().getResource("/scenarios/two-wheeled.scenario.xml").toURI());
        Scenario scenario = new ScenarioLoader().load(file);
        assertEquals("two wheeled robots", scenario.name());
        assertEquals(file.resolveSibling("wander.masl"), scenario.mission().orElseThrow(), "resolved next to the scenario");
        TestMission mission = new TestMission()
                .agent("k0", WheeledRobot.class, impl -> RobotPrograms.wander(impl, 1000))
                .agent("k1", WheeledRobot.class, impl -> RobotPrograms.wander(impl, 1000));
        Path output = Path.of("build", "pictures", "two-wheeled");
        SimulationResult result = new ScenarioRunner(scenario).run(mission, quick().withOutput(output));
        assertEquals(MissionOutcome.Status.STOPPED, result.outcome().status(), "ended by the scenario's duration");
        assertEquals(10.0, result.simulatedSeconds(), 1e-9);
        for (RunRecorder.Sample s : result.recorder().samples()) {
            assertTrue(Math.abs(s.x()) < 0.6 && Math.abs(s.y()) < 0.6, "stayed inside the walls: " + s);
        }
    }

    @Test
    void aSmallScenarioWritesAPictureWithEveryRobotsPath() throws Exception {
        Scenario scenario = scenario("""
                <physics seed="3" duration="6"/>
                <agent name="k0" model="wheeled"><pose x="-0.4" y="-0.4" heading="40"/></agent>
                <agent name="k1" model="wheeled"><pose x="0.4" y="0.3" heading="190"/></agent>
                <agent name="k2" model="wheeled"><pose x="-0.3" y="0.4" heading="-80"/></agent>
                <fault agent="k2" time="4"/>""");
        TestMission mission = new TestMission()
                .agent("k0", WheeledRobot.class, impl -> RobotPrograms.wander(impl, 1000))
                .agent("k1", WheeledRobot.class, impl -> RobotPrograms.wander(impl, 1000))
                .agent("k2", WheeledRobot.class, impl -> RobotPrograms.wander(impl, 1000));
        Path output = Path.of("build", "pictures", "wander");
        SimulationResult result = new ScenarioRunner(scenario).run(mission, quick().withOutput(output));
        assertEquals(5, result.files().size());
        BufferedImage image = ImageIO.read(output.resolve(ScenarioRunner.PICTURE).toFile());
        for (int robot = 0; robot < 3; robot++) {
            Color colour = TrajectoryPicture.colour(robot);
            long pixels = IntStream.range(0, image.getWidth() * image.getHeight())
                    .filter(i -> (image.getRGB(i % image.getWidth(), i / image.getWidth()) & 0xffffff) == (colour.getRGB() & 0xffffff))
                    .count();
            assertTrue(pixels > 200, "robot " + robot + "'s path drawn: " + pixels + " pixels");
        }
        String csv = Files.readString(output.resolve(ScenarioRunner.TRAJECTORIES));
        assertEquals(result.trajectoriesCsv(), csv);
        assertTrue(csv.startsWith("time,agent,x,y,z,heading\n0.000,k0,"), csv.substring(0, 60));
    }
}
