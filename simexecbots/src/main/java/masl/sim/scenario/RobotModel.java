package masl.sim.scenario;

import java.util.Arrays;
import java.util.Optional;
import masl.agents.MaamAtom;
import masl.agents.WheeledRobot;
import masl.runtime.AgentImplementation;

/**
 * The robot models SimExecBots can simulate: each names its agent type (descriptor and
 * implementation class in {@code agents/}) and its body.
 */
public enum RobotModel {

    /** Two-wheeled differential robot, Khepera-like: {@code WheeledRobot.xml}, {@code wheeled-robot.xode}. */
    WHEELED("wheeled", WheeledRobot.class, "WheeledRobot.xml"),
    /** Legged modular atom, MAAM-like: {@code MaamAtom.xml}, {@code maam-atom.xode}. */
    MAAM_ATOM("maam-atom", MaamAtom.class, "MaamAtom.xml");

    private final String scenarioName;
    private final Class<? extends AgentImplementation> implementation;
    private final String descriptor;

    RobotModel(String scenarioName, Class<? extends AgentImplementation> implementation, String descriptor) {
        this.scenarioName = scenarioName;
        this.implementation = implementation;
        this.descriptor = descriptor;
    }

    /** The name a scenario uses: {@code model="wheeled"}. */
    public String scenarioName() {
        return scenarioName;
    }

    /** The agent type's implementation class; a scenario may name a subclass instead. */
    public Class<? extends AgentImplementation> implementation() {
        return implementation;
    }

    /** The descriptor's file name, found on the class path (agents/): what a launcher imports for the type. */
    public String descriptor() {
        return descriptor;
    }

    public static Optional<RobotModel> named(String scenarioName) {
        return Arrays.stream(values()).filter(m -> m.scenarioName.equals(scenarioName)).findFirst();
    }
}
