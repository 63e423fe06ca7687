package masl.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import masl.runtime.diagnostic.Diagnostic;
import masl.sim.physics.PhysicsSettings;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Scenario files: every element read, every broken one reported with file, line and column. */
class ScenarioLoaderTest {

    @TempDir
    Path folder;

    private Scenario load(String text) throws ScenarioException {
        return new ScenarioLoader().load("s.xml", text, folder);
    }

    private List<String> errors(String text) {
        return assertThrows(ScenarioException.class, () -> load(text)).diagnostics().stream().map(Diagnostic::headline).toList();
    }

    @Test
    void readsEveryElement() throws Exception {
        Files.writeString(folder.resolve("arena.xode"), "<xode version=\"1.0r23\"><world/></xode>");
        Scenario scenario = load("""
                <scenario name="demo">
                  <physics step="0.005" iterations="30" gravity="0 0 -1.62" seed="42" friction="0.8"
                           mode="threaded" slicesPerStep="8" realTimeFactor="2" duration="12.5" contacts="3"/>
                  <world file="arena.xode"/>
                  <world resource="masl/agents/robots/wheeled-robot.xode"/>
                  <agent name="k0" model="wheeled"><pose x="0.5" y="-1" heading="90"/></agent>
                  <agent name="a0" model="maam-atom" class="masl.agents.MaamAtom"/>
                  <agent name="planner" class="masl.agents.Default"/>
                  <fault agent="k0" time="3"/>
                  <initialisation class="my.Setup"/>
                  <mission file="missions/demo.masl"/>
                  <output sample="0.25"/>
                </scenario>""");
        assertEquals("demo", scenario.name());
        assertEquals(new PhysicsSettings(0.005, 30, 0, 0, -1.62, 42, 0.8, 3, 2), scenario.physics());
        assertEquals(Scenario.Mode.THREADED, scenario.mode());
        assertEquals(8, scenario.slicesPerStep());
        assertEquals(12.5, scenario.duration());
        assertEquals(List.of(folder.resolve("arena.xode").toString(), "masl/agents/robots/wheeled-robot.xode"),
                scenario.worlds().stream().map(w -> w.name()).toList());
        assertEquals(List.of("k0", "a0", "planner"), scenario.agents().stream().map(Scenario.Agent::name).toList());
        Scenario.Agent k0 = scenario.agent("k0").orElseThrow();
        assertEquals(RobotModel.WHEELED, k0.model().orElseThrow());
        assertEquals(0.5, k0.x());
        assertEquals(-1, k0.y());
        assertEquals(Math.PI / 2, k0.heading(), 1e-12);
        assertEquals("s.xml:6:3", k0.location().toString());
        assertEquals(RobotModel.MAAM_ATOM, scenario.agent("a0").orElseThrow().model().orElseThrow());
        assertFalse(scenario.agent("planner").orElseThrow().isRobot());
        assertEquals("masl.agents.Default", scenario.agent("planner").orElseThrow().implementation().orElseThrow());
        assertEquals(3, scenario.faults().get(0).time());
        assertEquals("my.Setup", scenario.initialisation().orElseThrow().className());
        assertEquals(folder.resolve("missions/demo.masl"), scenario.mission().orElseThrow());
        assertEquals(0.25, scenario.samplePeriod());
    }

    @Test
    void anEmptyScenarioHasTheDefaults() throws Exception {
        Scenario scenario = load("<scenario/>");
        assertEquals("s.xml", scenario.name());
        assertEquals(PhysicsSettings.defaults().withRealTimeFactor(0), scenario.physics());
        assertEquals(Scenario.Mode.LOCK_STEP, scenario.mode());
        assertEquals(64, scenario.slicesPerStep());
        assertEquals(0, scenario.duration());
        assertTrue(scenario.agents().isEmpty());
        assertTrue(scenario.mission().isEmpty());
        assertEquals(0.1, scenario.samplePeriod());
    }

    @Test
    void everyErrorOfAFileIsReportedWithItsPositionInFileOrder() {
        List<String> errors = errors("""
                <scenario>
                  <physics step="-0.01" seed="x" gravity="0 -9.81" mode="fast"/>
                  <world file="missing.xode"/>
                  <agent name="k0" model="tank" colour="red"/>
                  <agent name="k0" model="wheeled"/>
                  <agent name="soft"><pose x="1"/></agent>
                  <fault agent="nobody" time="1"/>
                  <fault agent="soft" time="-1"/>
                  <robot name="r"/>
                  <mission/>
                  <mission file="a.masl"/>
                </scenario>""");
        assertEquals(List.of(
                "s.xml:2:3: error: step: -0.01 must be greater than 0",
                "s.xml:2:3: error: seed: 'x' is not a whole number",
                "s.xml:2:3: error: gravity: three numbers expected (x y z), got '0 -9.81'",
                "s.xml:2:3: error: mode: 'fast' is neither 'lock-step' nor 'threaded'",
                "s.xml:3:3: error: file 'missing.xode' not found (looked for " + folder.resolve("missing.xode") + ")",
                "s.xml:4:3: error: unknown attribute 'colour' on <agent>",
                "s.xml:4:3: error: model: unknown robot model 'tank' (known: wheeled, maam-atom)",
                "s.xml:5:3: error: agent 'k0' placed twice",
                "s.xml:6:22: error: <pose>: only a robot agent (with a model) has a pose",
                "s.xml:7:3: error: agent: no agent 'nobody' in this scenario",
                "s.xml:8:3: error: time: -1 must be at least 0",
                "s.xml:8:3: error: agent: 'soft' is not a wheeled robot; only they can fail",
                "s.xml:9:3: error: unknown element <robot> in <scenario>",
                "s.xml:10:3: error: <mission> needs the attribute 'file'",
                "s.xml:11:3: error: <mission> given twice"), errors);
    }

    @Test
    void countsAreWholeNumbersOfAtLeastOne() throws Exception {
        assertEquals(List.of(
                "s.xml:1:11: error: iterations: '2.5' is not a whole number from 1 to 10000",
                "s.xml:1:11: error: contacts: '0' is not a whole number from 1 to 256",
                "s.xml:1:11: error: slicesPerStep: 'many' is not a whole number from 1 to 1000000"),
                errors("<scenario><physics iterations=\"2.5\" contacts=\"0\" slicesPerStep=\"many\"/></scenario>"));
        assertEquals(1, load("<scenario><physics slicesPerStep=\"1\"/></scenario>").slicesPerStep(), "one slice per step");
    }

    /** A physics step cannot be interrupted: numbers that would make one run for hours are errors. */
    @Test
    void numbersThatWouldMakeAStepEndlessAreBounded() throws Exception {
        assertEquals(List.of(
                "s.xml:1:11: error: step: 2 must be from 0.000001 to 1 (seconds)",
                "s.xml:1:11: error: iterations: '2000000000' is not a whole number from 1 to 10000",
                "s.xml:1:11: error: contacts: '99999999999' is not a whole number from 1 to 256",
                "s.xml:1:11: error: realTimeFactor: 1e-9 must be 0 (as fast as possible) or from 0.001 to 1000",
                "s.xml:1:11: error: slicesPerStep: '2000000000' is not a whole number from 1 to 1000000"),
                errors("<scenario><physics step=\"2\" iterations=\"2000000000\" contacts=\"99999999999\""
                        + " realTimeFactor=\"1e-9\" slicesPerStep=\"2000000000\"/></scenario>"));
        Scenario largest = load("<scenario><physics step=\"1\" iterations=\"10000\" contacts=\"256\" realTimeFactor=\"1000\""
                + " slicesPerStep=\"1000000\"/></scenario>");
        assertEquals(10000, largest.physics().solverIterations());
        assertEquals(1000000, largest.slicesPerStep());
    }

    @Test
    void malformedXmlIsOneLocatedError() {
        List<String> errors = errors("<scenario>\n  <agent name=\"k0\">\n</scenario>");
        assertEquals(1, errors.size());
        assertTrue(errors.get(0).matches("s\\.xml:3:\\d+: error: .*"), errors.get(0));
    }

    @Test
    void theRootMustBeAScenario() {
        assertEquals(List.of("s.xml:1:1: error: the root element must be <scenario>, not <xode>"), errors("<xode/>"));
    }

    @Test
    void badIdentifiersAndClassNamesAreErrors() {
        assertEquals(List.of(
                "s.xml:1:11: error: name: 'two words' is not a MASL identifier",
                "s.xml:1:52: error: class: '1x' is not a Java class name"),
                errors("<scenario><agent name=\"two words\" model=\"wheeled\"/><initialisation class=\"1x\"/></scenario>"));
    }

    @Test
    void anExternalEntityIsNeverRead() throws IOException {
        Path secret = Files.writeString(folder.resolve("secret.txt"), "TOP-SECRET");
        List<String> errors = errors("<?xml version=\"1.0\"?>\n<!DOCTYPE scenario [<!ENTITY x SYSTEM \"" + secret.toUri()
                + "\">]>\n<scenario name=\"&x;\"/>");
        assertEquals(1, errors.size());
        assertTrue(errors.get(0).startsWith("s.xml:3:"), errors.get(0));
        assertFalse(errors.get(0).contains("TOP-SECRET"));
    }

    @Test
    void aMissingFileIsALocatedError() {
        Path missing = folder.resolve("none.xml");
        ScenarioException e = assertThrows(ScenarioException.class, () -> new ScenarioLoader().load(missing));
        assertTrue(e.getMessage().startsWith(missing + ":1:1: error: cannot read the scenario"), e.getMessage());
    }
}
