package masl.sim.scenario;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import masl.sim.physics.PhysicsSettings;
import masl.sim.xode.SourceLocation;
import masl.sim.xode.XodeSource;

/**
 * A loaded scenario file (components.md, "SimExecBots"): the physics, the world files, the agents
 * with their robot models and initial poses, faults to inject, an initialisation class, the
 * mission file and the output settings. Immutable; see {@link ScenarioLoader} for the format.
 *
 * @param name           the scenario's name (its {@code name} attribute, else the file name)
 * @param source         where it was read from, for messages
 * @param physics        step, solver iterations, gravity, seed, friction, real-time factor
 * @param mode           lock-step (reproducible) or physics on its own thread
 * @param slicesPerStep  lock-step: agent slices between two world steps while agents are runnable
 * @param duration       simulated seconds after which the run is stopped; 0 for no limit
 * @param worlds         XODE world files, loaded in order, unprefixed
 * @param agents         the agents the scenario places, in file order
 * @param faults         faults injected at given simulated times
 * @param initialisation the class run once before the programs start, if any
 * @param mission        the mission's {@code .masl} file, resolved against the scenario's folder, if given
 * @param samplePeriod   simulated seconds between two trajectory samples
 */
public record Scenario(String name, String source, PhysicsSettings physics, Mode mode, int slicesPerStep, double duration,
        List<XodeSource> worlds, List<Agent> agents, List<Fault> faults, Optional<Initialisation> initialisation,
        Optional<Path> mission, double samplePeriod) {

    /** How physics and agents share time. */
    public enum Mode {
        /** One thread alternates agents and physics steps: the same seed gives the same run. */
        LOCK_STEP,
        /** Physics on its own thread at a fixed step, agents on a pool. */
        THREADED
    }

    /**
     * An agent the scenario places. A robot agent has a model (and a body); a software agent has
     * none and may name its implementation class.
     *
     * @param name           the MASL name of the agent in the mission's declarations
     * @param model          its robot model, empty for a software agent
     * @param implementation an implementation class to use instead of the model's or the type's
     * @param descriptor     a descriptor file for the agent's type, if the scenario names one
     * @param body           an XODE body replacing the model's (same body and joint names), if given
     * @param x              initial position (m)
     * @param y              initial position (m)
     * @param heading        initial heading (rad, counter-clockwise from +X)
     * @param location       where the agent is declared in the scenario
     */
    public record Agent(String name, Optional<RobotModel> model, Optional<String> implementation, Optional<Path> descriptor,
            Optional<XodeSource> body, double x, double y, double heading, SourceLocation location) {

        public boolean isRobot() {
            return model.isPresent();
        }
    }

    /** The class run once before the programs start, an {@link ScenarioInitialiser}. */
    public record Initialisation(String className, SourceLocation location) { }

    /** At simulated time {@code time} the robot {@code agent} fails: motors stop, battery reads 0. */
    public record Fault(String agent, double time, SourceLocation location) { }

    public Scenario {
        worlds = List.copyOf(worlds);
        agents = List.copyOf(agents);
        faults = List.copyOf(faults);
    }

    /** The agent the scenario places under that name. */
    public Optional<Agent> agent(String agentName) {
        return agents.stream().filter(a -> a.name().equals(agentName)).findFirst();
    }
}
