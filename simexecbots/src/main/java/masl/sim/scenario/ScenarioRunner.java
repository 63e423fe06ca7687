package masl.sim.scenario;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.AtomicBoolean;
import masl.agents.MaamAtom;
import masl.agents.WheeledRobot;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.Scheduler;
import masl.runtime.trace.JsonLinesTrace;
import masl.runtime.trace.Trace;
import masl.sim.clock.LockStepScheduler;
import masl.sim.clock.ThreadedSimulationScheduler;
import masl.sim.output.RunRecorder;
import masl.sim.output.SimulatedTimeTrace;
import masl.sim.output.TrajectoryPicture;
import masl.sim.physics.PhysicsWorld;
import masl.sim.robots.SimulatedAtom;
import masl.sim.robots.SimulatedWheeledRobot;
import masl.sim.xode.SourceLocation;
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
        ClassLoader classes = options.classes() != null ? options.classes() : program.getClass().getClassLoader();
        checkPlacedAgentsAreDeclared(program);
        try (PhysicsWorld world = new PhysicsWorld(scenario.physics())) {
            RunRecorder recorder = new RunRecorder(Math.max(1, Math.round(scenario.samplePeriod() / scenario.physics().stepSize())));
            loadWorlds(world);
            SimulatedAtom.Latches latches = new SimulatedAtom.Latches((attached, foot, otherFoot) ->
                    recorder.event(agentOf(foot), attached ? "attach" : "detach", foot + " " + otherFoot));
            Map<String, AgentImplementation> implementations = new HashMap<>();
            List<SimulatedRobot> robots = new ArrayList<>();
            List<MissionProgram.AgentSpec> specs = program.agents();
            for (int proxyId = 0; proxyId < specs.size(); proxyId++) {
                MissionProgram.AgentSpec spec = specs.get(proxyId);
                AgentImplementation implementation = implementation(spec, classes);
                Scenario.Agent placed = scenario.agent(spec.name()).orElse(null);
                if (placed != null && placed.isRobot()) {
                    SimulatedRobot robot = bindBody(world, placed, implementation, proxyId, latches);
                    robots.add(robot);
                    recorder.track(robot.name(), robot.mainBody());
                }
                implementations.put(spec.name(), implementation);
            }
            Simulation simulation = new Simulation(scenario, world, robots, recorder);
            initialise(simulation, classes);
            return runMission(program, options, simulation, implementations);
        }
    }

    private SimulationResult runMission(MissionProgram program, RunOptions options, Simulation simulation,
            Map<String, AgentImplementation> implementations) throws InterruptedException, IOException {
        PhysicsWorld world = simulation.world();
        RunRecorder recorder = simulation.recorder();
        StringBuilder traceText = new StringBuilder();
        JsonLinesTrace jsonTrace = new JsonLinesTrace(traceText);
        // The file gets simulated time stamps, so that lock-step runs repeat byte for byte.
        Trace fileTrace = new SimulatedTimeTrace(() -> world.stepCount() * Math.round(scenario.physics().stepSize() * 1e9),
                jsonTrace);
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

        // The recorder first: events of a step's listeners are stamped with that step's time.
        world.addStepListener(recorder);
        world.addStepListener(new FaultInjector(simulation, recorder));
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
        return new SimulationResult(outcome, simulated, recorder, traceText.toString(), files);
    }

    /** Injects the scenario's faults and records empty batteries, after each step. */
    private final class FaultInjector implements PhysicsWorld.StepListener {
        private final Simulation simulation;
        private final RunRecorder recorder;
        private final List<Scenario.Fault> pending;
        private final Map<String, Boolean> empty = new LinkedHashMap<>();

        FaultInjector(Simulation simulation, RunRecorder recorder) {
            this.simulation = simulation;
            this.recorder = recorder;
            this.pending = new ArrayList<>(scenario.faults());
        }

        @Override
        public void afterStep(PhysicsWorld world) {
            double now = world.simulatedTime();
            pending.removeIf(fault -> {
                if (now < fault.time() - 1e-9) {
                    return false;
                }
                simulation.robot(fault.agent()).hardware(SimulatedWheeledRobot.class).fail();
                recorder.event(fault.agent(), "fault", "motors stopped, battery 0");
                return true;
            });
            for (SimulatedRobot robot : simulation.robots().values()) {
                if (robot.hardware() instanceof SimulatedWheeledRobot wheeled && wheeled.battery() <= 0
                        && empty.put(robot.name(), true) == null) {
                    recorder.event(robot.name(), "battery-empty", "");
                }
            }
        }
    }

    private List<Path> writeOutput(Path folder, Simulation simulation, MissionOutcome outcome, String trace, double simulated)
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
        List<String> errors = new ArrayList<>();
        for (Scenario.Agent agent : scenario.agents()) {
            if (program.agents().stream().noneMatch(spec -> spec.name().equals(agent.name()))) {
                errors.add(agent.location() + ": error: agent '" + agent.name() + "' is not declared by the mission (it declares "
                        + program.agents().stream().map(MissionProgram.AgentSpec::name).toList() + ")");
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
                throw new ScenarioException(e.problems().stream().map(XodeProblem::format).toList());
            }
        }
    }

    /** Makes the implementation of one program agent: the scenario's class, the model's, or the declared type's. */
    private AgentImplementation implementation(MissionProgram.AgentSpec spec, ClassLoader classes) throws ScenarioException {
        Scenario.Agent placed = scenario.agent(spec.name()).orElse(null);
        SourceLocation where = placed != null ? placed.location() : new SourceLocation(scenario.source(), 1, 1);
        Class<?> declared = load(spec.typeClassName(), classes, where, "type of agent '" + spec.name() + "'");
        Class<?> chosen = declared;
        if (placed != null && placed.implementation().isPresent()) {
            chosen = load(placed.implementation().get(), classes, where, "class of agent '" + spec.name() + "'");
        } else if (placed != null && placed.isRobot()) {
            chosen = placed.model().orElseThrow().implementation();
        }
        if (placed != null && placed.isRobot() && !placed.model().orElseThrow().implementation().isAssignableFrom(chosen)) {
            throw located(where, "class " + chosen.getName() + " of agent '" + spec.name() + "' does not extend "
                    + placed.model().orElseThrow().implementation().getName() + ", the class of model '"
                    + placed.model().orElseThrow().scenarioName() + "'");
        }
        if (!declared.isAssignableFrom(chosen)) {
            throw located(where, "agent '" + spec.name() + "' is declared a " + declared.getName() + " by the mission, but "
                    + chosen.getName() + " is not one");
        }
        if (!AgentImplementation.class.isAssignableFrom(chosen)) {
            throw located(where, "class " + chosen.getName() + " does not extend masl.runtime.AgentImplementation");
        }
        try {
            return (AgentImplementation) chosen.getConstructor().newInstance();
        } catch (ReflectiveOperationException | RuntimeException e) {
            throw located(where, "cannot make an instance of " + chosen.getName() + " for agent '" + spec.name() + "': "
                    + describe(e));
        }
    }

    private SimulatedRobot bindBody(PhysicsWorld world, Scenario.Agent placed, AgentImplementation implementation, int proxyId,
            SimulatedAtom.Latches latches) throws ScenarioException {
        RobotModel model = placed.model().orElseThrow();
        String prefix = placed.name() + ".";
        try {
            switch (model) {
                case WHEELED -> {
                    SimulatedWheeledRobot body = SimulatedWheeledRobot.load(world,
                            placed.body().orElse(SimulatedWheeledRobot.BODY), prefix, placed.x(), placed.y(), placed.heading());
                    ((WheeledRobot) implementation).attachHardware(body);
                    return new SimulatedRobot(placed.name(), model, body.chassis(), body);
                }
                case MAAM_ATOM -> {
                    SimulatedAtom body = SimulatedAtom.load(world, placed.body().orElse(SimulatedAtom.BODY), prefix,
                            placed.x(), placed.y(), placed.heading(), latches);
                    latches.register(proxyId, body);
                    ((MaamAtom) implementation).attachHardware(body);
                    return new SimulatedRobot(placed.name(), model, body.mainBody(), body);
                }
                default -> throw new IllegalStateException(model.name());
            }
        } catch (XodeException e) {
            List<String> errors = new ArrayList<>();
            errors.add(placed.location() + ": error: the body of agent '" + placed.name() + "' cannot be loaded:");
            e.problems().stream().map(XodeProblem::format).forEach(errors::add);
            throw new ScenarioException(errors);
        }
    }

    private void initialise(Simulation simulation, ClassLoader classes) throws ScenarioException {
        if (scenario.initialisation().isEmpty()) {
            return;
        }
        Scenario.Initialisation initialisation = scenario.initialisation().get();
        Class<?> type = load(initialisation.className(), classes, initialisation.location(), "initialisation class");
        if (!ScenarioInitialiser.class.isAssignableFrom(type)) {
            throw located(initialisation.location(), "initialisation class " + type.getName() + " does not implement "
                    + ScenarioInitialiser.class.getName());
        }
        try {
            ((ScenarioInitialiser) type.getConstructor().newInstance()).initialise(simulation);
        } catch (Exception e) {
            throw located(initialisation.location(), "initialisation class " + type.getName() + " failed: " + describe(e));
        }
    }

    private static Class<?> load(String name, ClassLoader classes, SourceLocation where, String role) throws ScenarioException {
        try {
            return Class.forName(name, false, classes);
        } catch (ClassNotFoundException | LinkageError e) {
            throw located(where, role + ": class " + name + " not found");
        }
    }

    private static ScenarioException located(SourceLocation where, String message) {
        return new ScenarioException(List.of(where + ": error: " + message));
    }

    private static String describe(Throwable e) {
        Throwable cause = e instanceof java.lang.reflect.InvocationTargetException && e.getCause() != null ? e.getCause() : e;
        return cause.getClass().getSimpleName() + (cause.getMessage() == null ? "" : ": " + cause.getMessage());
    }

    /** The agent of a prefixed body name: {@code a0.frontLeg} belongs to {@code a0}. */
    private static String agentOf(String body) {
        int dot = body.indexOf('.');
        return dot < 0 ? body : body.substring(0, dot);
    }
}
