package masl.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.sim.physics.PhysicsWorld;
import masl.sim.robots.SimulatedWheeledRobot;
import masl.sim.scenario.RunOptions;
import masl.sim.scenario.Scenario;
import masl.sim.scenario.ScenarioLoader;
import masl.sim.scenario.ScenarioRunner;
import masl.sim.scenario.SimulationResult;
import masl.sim.xode.XodeSource;

/**
 * The simulation benchmark: {@value #ROBOTS} wheeled robots on a floor, step
 * 0.01 s, lock-step, each driven by a MASL program that sets its wheel speeds every step, against
 * a bare loop that loads the same bodies into an ode4j world of the same settings and sets the
 * same speeds before every step, in Java, on one thread. Both report simulated seconds per
 * second of elapsed time.
 *
 * <pre>
 * asynchronous entry main (true) {
 *   while (true) { .setSpeeds(5.0, 4.0); .sleep(10); }
 * }
 * </pre>
 */
final class MaslSimulation {

    static final int ROBOTS = 100;
    private static final double SIMULATED_SECONDS = 5;
    private static final double LEFT = 5.0;
    private static final double RIGHT = 4.0;

    private final Scenario scenario;
    private final MissionProgram program;

    private MaslSimulation(Scenario scenario, MissionProgram program) {
        this.scenario = scenario;
        this.program = program;
    }

    /** Writes the scenario and its floor to a temporary folder, and translates and compiles the mission. */
    static MaslSimulation prepare() throws Exception {
        Path folder = Files.createTempDirectory("masl-bench-sim");
        folder.toFile().deleteOnExit();
        Files.writeString(folder.resolve("floor.xode"), """
                <xode version="1.0r23"><world><space>
                  <geom name="floor"><plane a="0" b="0" c="1" d="0"/></geom>
                </space></world></xode>
                """);
        folder.resolve("floor.xode").toFile().deleteOnExit();
        Scenario scenario = new ScenarioLoader().load("bench.scenario.xml", scenarioXml(), folder);
        MissionProgram program = MaslLockStep.compile(missionSource()).program();
        return new MaslSimulation(scenario, program);
    }

    /**
     * The MASL run: simulated seconds per second of elapsed time, or with {@code cpuTime} of the
     * process's processor time (both loops run on one thread; other jobs of the machine do not
     * change that figure). The run is ended by the scenario's duration.
     */
    Callable<Double> masl(boolean cpuTime) {
        return () -> {
            long start = clock(cpuTime);
            SimulationResult result = new ScenarioRunner(scenario).run(program,
                    RunOptions.defaults().withTimeout(Duration.ofMinutes(5)).withJournal(new StringBuilder()));
            long elapsed = clock(cpuTime) - start;
            if (result.outcome().status() != MissionOutcome.Status.STOPPED) {
                throw new IllegalStateException("the simulated mission ended " + result.outcome().status()
                        + result.outcome().failure().map(f -> ": " + f).orElse(""));
            }
            return result.simulatedSeconds() / (elapsed / 1e9);
        };
    }

    /** The bare loop over the same bodies: simulated seconds per second, as {@link #masl(boolean)}. */
    Callable<Double> bare(boolean cpuTime) {
        return () -> {
            long start = clock(cpuTime);
            try (PhysicsWorld world = new PhysicsWorld(scenario.physics())) {
                for (XodeSource floor : scenario.worlds()) {
                    world.load(floor, "");
                }
                List<SimulatedWheeledRobot> robots = new ArrayList<>();
                for (Scenario.Agent agent : scenario.agents()) {
                    robots.add(SimulatedWheeledRobot.load(world, agent.name() + ".", agent.x(), agent.y(), agent.heading()));
                }
                while (world.simulatedTime() < SIMULATED_SECONDS - 1e-9) {
                    for (SimulatedWheeledRobot robot : robots) {
                        robot.setWheelSpeeds(LEFT, RIGHT);
                    }
                    world.step();
                }
                return world.simulatedTime() / ((clock(cpuTime) - start) / 1e9);
            }
        };
    }

    private static long clock(boolean cpuTime) {
        if (!cpuTime) {
            return System.nanoTime();
        }
        return Bench.processCpuNanos();
    }

    /** Robots on a 10-wide grid, 0.5 m apart, all facing +X: they drive along without meeting. */
    private static String scenarioXml() {
        StringBuilder agents = new StringBuilder();
        for (int i = 0; i < ROBOTS; i++) {
            agents.append(String.format(Locale.ROOT, "  <agent name=\"r%d\" model=\"wheeled\"><pose x=\"%.1f\" y=\"%.1f\" heading=\"0\"/></agent>%n",
                    i, (i % 10) * 0.5, (i / 10) * 0.5));
        }
        return """
                <scenario name="bench">
                  <physics step="0.01" mode="lock-step" duration="%s"/>
                  <world file="floor.xode"/>
                %s</scenario>
                """.formatted(SIMULATED_SECONDS, agents);
    }

    private static String missionSource() {
        String names = IntStream.range(0, ROBOTS).mapToObj(i -> "r" + i).collect(Collectors.joining(", "));
        return """
                import WheeledRobot.xml as WheeledRobot;
                WheeledRobot %s = newAgent(WheeledRobot);
                asynchronous entry main (true) {
                  while (true) {
                    .setSpeeds(%s, %s);
                    .sleep(10);
                  }
                }
                """.formatted(names, LEFT, RIGHT);
    }
}
