package masl.sim.scenario;

import java.lang.reflect.InvocationTargetException;
import java.util.ArrayList;
import java.util.List;
import masl.agents.MaamAtom;
import masl.agents.WheeledRobot;
import masl.runtime.AgentImplementation;
import masl.runtime.MissionProgram;
import masl.runtime.diagnostic.Diagnostic;
import masl.sim.physics.PhysicsWorld;
import masl.sim.robots.SimulatedAtom;
import masl.sim.robots.SimulatedWheeledRobot;
import masl.sim.xode.SourceLocation;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeProblem;

/**
 * Makes what a scenario run needs from classes: each agent's implementation (the scenario's class,
 * the robot model's, or the declared type's), a robot's simulated body bound to it, and the
 * initialisation. Every failure is a {@link ScenarioException} located in the scenario.
 */
final class AgentBinder {

    private final Scenario scenario;
    private final ClassLoader classes;

    AgentBinder(Scenario scenario, ClassLoader classes) {
        this.scenario = scenario;
        this.classes = classes;
    }

    /** Makes the implementation of one program agent: the scenario's class, the model's, or the declared type's. */
    AgentImplementation implementation(MissionProgram.AgentSpec spec) throws ScenarioException {
        Scenario.Agent placed = scenario.agent(spec.name()).orElse(null);
        SourceLocation where = placed != null ? placed.location() : new SourceLocation(scenario.source(), 1, 1);
        Class<?> declared = load(spec.typeClassName(), where, "type of agent '" + spec.name() + "'");
        Class<?> chosen = declared;
        if (placed != null && placed.implementation().isPresent()) {
            chosen = load(placed.implementation().get(), where, "class of agent '" + spec.name() + "'");
        }
        RobotModel model = placed != null ? placed.model().orElse(null) : null;
        if (model != null && placed.implementation().isEmpty()) {
            chosen = model.implementation();
        }
        if (model != null && !model.implementation().isAssignableFrom(chosen)) {
            throw located(where, "class " + chosen.getName() + " of agent '" + spec.name() + "' does not extend "
                    + model.implementation().getName() + ", the class of model '" + model.scenarioName() + "'");
        }
        if (!declared.isAssignableFrom(chosen)) {
            throw located(where, "agent '" + spec.name() + "' is declared a " + declared.getName()
                    + " by the mission, but " + chosen.getName() + " is not one");
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

    /** Loads the body of a robot agent at its pose and attaches it to the agent's implementation. */
    SimulatedRobot bindBody(PhysicsWorld world, Scenario.Agent placed, AgentImplementation implementation, int proxyId,
            SimulatedAtom.Latches latches) throws ScenarioException {
        RobotModel model = placed.model().orElseThrow();
        String prefix = placed.name() + ".";
        try {
            switch (model) {
                case WHEELED -> {
                    SimulatedWheeledRobot body = SimulatedWheeledRobot.load(world,
                            placed.body().orElse(SimulatedWheeledRobot.BODY), prefix,
                            placed.x(), placed.y(), placed.heading());
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
            List<Diagnostic> errors = new ArrayList<>();
            errors.add(placed.location().error("the body of agent '" + placed.name() + "' cannot be loaded:"));
            e.problems().stream().map(XodeProblem::diagnostic).forEach(errors::add);
            throw new ScenarioException(errors);
        }
    }

    /** Runs the scenario's initialisation class, if it names one. */
    void initialise(Simulation simulation) throws ScenarioException {
        if (scenario.initialisation().isEmpty()) {
            return;
        }
        Scenario.Initialisation initialisation = scenario.initialisation().get();
        Class<?> type = load(initialisation.className(), initialisation.location(), "initialisation class");
        if (!ScenarioInitialiser.class.isAssignableFrom(type)) {
            throw located(initialisation.location(), "initialisation class " + type.getName() + " does not implement "
                    + ScenarioInitialiser.class.getName());
        }
        try {
            ((ScenarioInitialiser) type.getConstructor().newInstance()).initialise(simulation);
        } catch (Exception e) {
            throw located(initialisation.location(),
                    "initialisation class " + type.getName() + " failed: " + describe(e));
        }
    }

    private Class<?> load(String name, SourceLocation where, String role) throws ScenarioException {
        try {
            return Class.forName(name, false, classes);
        } catch (ClassNotFoundException | LinkageError e) {
            throw located(where, role + ": class " + name + " not found");
        }
    }

    private static ScenarioException located(SourceLocation where, String message) {
        return new ScenarioException(List.of(where.error(message)));
    }

    private static String describe(Throwable e) {
        Throwable cause = e instanceof InvocationTargetException && e.getCause() != null ? e.getCause() : e;
        return cause.getClass().getSimpleName() + (cause.getMessage() == null ? "" : ": " + cause.getMessage());
    }
}
