package masl.sim.scenario;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.AtomicBoolean;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.trace.JsonLinesTrace;
import masl.runtime.trace.Trace;
import masl.sim.clock.LockStepScheduler;
import masl.sim.clock.ThreadedSimulationScheduler;
import masl.sim.output.RunRecorder;
import masl.sim.output.SimulatedTimeTrace;
import masl.sim.output.TrajectoryPicture;
import masl.sim.physics.PhysicsWorld;
import masl.sim.robots.SimulatedAtom;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeProblem;
import masl.sim.xode.XodeSource;

/**
 * Runs a translated mission ({@link MissionProgram}) in a scenario: builds the physics world from
 * the scenario's world files, loads a body for every robot agent at its initial pose, gives each
 * agent its implementation (a robot's bound to its simulated hardware), runs the initialisation
 * class, then runs the mission in lock-step or with physics on its own thread, recording
 * trajectories and events. This is the API {@code masl run --sim SCENARIO} calls.
 *
 * <pre>{@code
 * Scenario scenario = new ScenarioLoader().load(Path.of("sweep.scenario.xml"));
 * SimulationResult result = new ScenarioRunner(scenario)
 *         .run(program, RunOptions.defaults().withJournal(System.out).withOutput(Path.of("out")));
 * }</pre>
 *
 * <p>Agents are matched by name: a program agent the scenario places gets the scenario's model
 * and class; one it does not place is a software agent of its declared type. The run ends when the
 * mission ends, when the scenario's {@code duration} of simulated time has passed (outcome
 * {@code STOPPED}; in lock-step exactly then, with the physics thread a few steps later), or at
 * the wall-clock timeout. A runner may run its scenario any number of times.
 */
public final class ScenarioRunner {

    /** Names of the files written to the output folder. */
    public static final String TRAJECTORIES = "trajectories.csv";
    public static final String EVENTS = "events.jsonl";
    public static final String TRACE = "trace.jsonl";
    public static final String JOURNAL = "journal.txt";
    public static final String PICTURE = "trajectories.png";

    private final Scenario scenario;

    public ScenarioRunner(Scenario scenario) {
        this.scenario = scenario;
    }

    public Scenario scenario() {
        return scenario;
    }

    /**
     * Runs {@code program} in this scenario.
     *
     * @throws ScenarioException    when the scenario does not fit the program (an agent it places is
     *                              not declared, a model does not implement the declared type, a class
     *                              cannot be loaded or made) or a world file has errors; nothing ran then
     * @throws InterruptedException when interrupted while the mission runs
     * @throws IOException          when an output file cannot be written
     */
    public SimulationResult run(MissionProgram program, RunOptions options)
            throws ScenarioException, InterruptedException, IOException {
        AgentBinder binder = new AgentBinder(scenario,
                options.classes() != null ? options.classes() : program.getClass().getClassLoader());
        checkPlacedAgentsAreDeclared(program);
        try (PhysicsWorld world = new PhysicsWorld(scenario.physics())) {
            long sampleSteps = Math.max(1, Math.round(scenario.samplePeriod() / scenario.physics().stepSize()));
            RunRecorder recorder = new RunRecorder(sampleSteps);
            loadWorlds(world);
            SimulatedAtom.Latches latches = new SimulatedAtom.Latches((attached, foot, otherFoot) ->
                    recorder.event(agentOf(foot), attached ? "attach" : "detach", foot + " " + otherFoot));
            Map<String, AgentImplementation> implementations = new HashMap<>();
            List<SimulatedRobot> robots = new ArrayList<>();
            List<MissionProgram.AgentSpec> specs = program.agents();
            for (int proxyId = 0; proxyId < specs.size(); proxyId++) {
                MissionProgram.AgentSpec spec = specs.get(proxyId);
                AgentImplementation implementation = binder.implementation(spec);
                Scenario.Agent placed = scenario.agent(spec.name()).orElse(null);
                if (placed != null && placed.isRobot()) {
                    SimulatedRobot robot = binder.bindBody(world, placed, implementation, proxyId, latches);
                    robots.add(robot);
                    recorder.track(robot.name(), robot.mainBody());
                }
                implementations.put(spec.name(), implementation);
            }
            if (!world.warnings().isEmpty()) {
                options.warned().accept(world.warnings());
            }
            Simulation simulation = new Simulation(scenario, world, robots, recorder);
            binder.initialise(simulation);
            return runMission(program, options, simulation, implementations);
        }
    }

    private SimulationResult runMission(MissionProgram program, RunOptions options, Simulation simulation,
            Map<String, AgentImplementation> implementations) throws InterruptedException, IOException {
        PhysicsWorld world = simulation.world();
        RunRecorder recorder = simulation.recorder();
        StringBuilder traceText = new StringBuilder();
        JsonLinesTrace jsonTrace = new JsonLinesTrace(traceText, options.traceLimit());
        // The file gets simulated time stamps, so that lock-step runs repeat byte for byte.
        long stepNanos = Math.round(scenario.physics().stepSize() * 1e9);
        Trace fileTrace = new SimulatedTimeTrace(() -> world.stepCount() * stepNanos, jsonTrace);
        Trace trace = event -> {
            fileTrace.record(event);
            options.trace().record(event);
        };
        Scheduler scheduler = scenario.mode() == Scenario.Mode.LOCK_STEP
                ? new LockStepScheduler(world, scenario.physics().seed(), scenario.slicesPerStep())
                : new ThreadedSimulationScheduler(world);
        Mission.Builder builder = Mission.builder().scheduler(scheduler).trace(trace);
        if (options.journal() != null) {
            builder.journal(options.journal());
        }
        program.configure(builder, spec -> implementations.get(spec.name()));
        Mission mission = builder.build();
        options.ready().accept(mission);

        // The recorder first: events of a step's listeners are stamped with that step's time.
        world.addStepListener(recorder);
        world.addStepListener(new FaultInjector(simulation, recorder));
        world.addStepListener(stepped -> options.progress().accept(stepped.simulatedTime()));
        if (scenario.duration() > 0) {
            AtomicBoolean stopped = new AtomicBoolean();
            world.addStepListener(stepped -> {
                if (stepped.simulatedTime() >= scenario.duration() - 1e-9 && stopped.compareAndSet(false, true)) {
                    if (scheduler instanceof LockStepScheduler lockStep) {
                        lockStep.halt();
                    }
                    mission.stop();
                }
            });
        }
        recorder.sampleNow(world);
        MissionOutcome outcome = mission.run(options.timeout());
        jsonTrace.flush();
        double simulated = world.simulatedTime();
        List<Path> files = options.output().isPresent()
                ? writeOutput(options.output().get(), simulation, outcome, traceText.toString(), simulated)
                : List.of();
        return new SimulationResult(outcome, simulated, recorder, traceText.toString(), files, jsonTrace.wasCut());
    }

    private List<Path> writeOutput(Path folder, Simulation simulation, MissionOutcome outcome, String trace,
            double simulated)
            throws IOException {
        Files.createDirectories(folder);
        RunRecorder recorder = simulation.recorder();
        StringBuilder csv = new StringBuilder();
        recorder.writeTrajectoriesCsv(csv);
        StringBuilder events = new StringBuilder();
        recorder.writeEventsJsonLines(events);
        List<Path> written = new ArrayList<>();
        written.add(Files.writeString(folder.resolve(TRAJECTORIES), csv, StandardCharsets.UTF_8));
        written.add(Files.writeString(folder.resolve(EVENTS), events, StandardCharsets.UTF_8));
        written.add(Files.writeString(folder.resolve(TRACE), trace, StandardCharsets.UTF_8));
        written.add(Files.writeString(folder.resolve(JOURNAL), outcome.journal(), StandardCharsets.UTF_8));
        Path picture = folder.resolve(PICTURE);
        String title = String.format(Locale.ROOT, "%s: %.1f s simulated, %s", scenario.name(), simulated,
                outcome.status().name().toLowerCase(Locale.ROOT));
        new TrajectoryPicture(800).write(picture, title, recorder.samples(), recorder.events(),
                simulation.world().staticBoxOutlines());
        written.add(picture);
        return written;
    }

    private void checkPlacedAgentsAreDeclared(MissionProgram program) throws ScenarioException {
        List<Diagnostic> errors = new ArrayList<>();
        for (Scenario.Agent agent : scenario.agents()) {
            if (program.agents().stream().noneMatch(spec -> spec.name().equals(agent.name()))) {
                errors.add(agent.location().error("agent '" + agent.name()
                        + "' is not declared by the mission (it declares "
                        + program.agents().stream().map(MissionProgram.AgentSpec::name).toList() + ")"));
            }
        }
        if (!errors.isEmpty()) {
            throw new ScenarioException(errors);
        }
    }

    private void loadWorlds(PhysicsWorld world) throws ScenarioException {
        for (XodeSource source : scenario.worlds()) {
            try {
                world.load(source, "");
            } catch (XodeException e) {
                throw new ScenarioException(e.problems().stream().map(XodeProblem::diagnostic).toList());
            }
        }
    }

    /** The agent of a prefixed body name: {@code a0.frontLeg} belongs to {@code a0}. */
    private static String agentOf(String body) {
        int dot = body.indexOf('.');
        return dot < 0 ? body : body.substring(0, dot);
    }
}
