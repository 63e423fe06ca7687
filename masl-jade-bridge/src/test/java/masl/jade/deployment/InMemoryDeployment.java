package masl.jade.deployment;

import java.time.Duration;
import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;
import masl.jade.TestPrograms;
import masl.runtime.AgentImplementation;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.trace.Trace;
import masl.testing.jade.DeployedInMemory;

/**
 * A mission whose named agents are deployed to containers in this JVM ({@link DeployedInMemory}),
 * the test programs' types, each agent's object of the class its type names.
 */
public final class InMemoryDeployment {

    private InMemoryDeployment() {
    }

    /**
     * How the mission ended, how many messages went from the containers to the mission and back, and
     * how many of each kind either way ({@link DeployedInMemory.Run#kinds}).
     */
    public record Run(MissionOutcome outcome, int messagesFromContainer, int messagesToContainer,
            Map<String, Integer> kinds) {
    }

    public static Run run(Supplier<MissionProgram> program, Set<String> deployed, Duration timeout)
            throws InterruptedException {
        Map<String, String> containerOfAgent = new HashMap<>();
        deployed.forEach(agent -> containerOfAgent.put(agent, "c2"));
        return run(program, containerOfAgent, timeout);
    }

    /**
     * The agents {@code containerOfAgent} names deployed to those containers, each joined to the
     * mission by wires of its own; the agents' objects are of the class each names, made anew.
     */
    public static Run run(Supplier<MissionProgram> program, Map<String, String> containerOfAgent, Duration timeout)
            throws InterruptedException {
        return run(program, containerOfAgent, Trace.NONE, new DeployedInMemory.Wires(), timeout);
    }

    /** As {@link #run(Supplier, Map, Duration)}, recording to {@code trace}, over {@code wires}, which the test may cut. */
    public static Run run(Supplier<MissionProgram> program, Map<String, String> containerOfAgent, Trace trace,
            DeployedInMemory.Wires wires, Duration timeout) throws InterruptedException {
        DeployedInMemory.Run run = DeployedInMemory.run(program, containerOfAgent, InMemoryDeployment::newAgent,
                TestPrograms::type, trace, wires, timeout);
        return new Run(run.outcome(), run.messagesFromContainers(), run.messagesToContainers(), run.kinds());
    }

    private static AgentImplementation newAgent(MissionProgram.AgentSpec spec) throws ReflectiveOperationException {
        return (AgentImplementation) Class.forName(spec.typeClassName()).getConstructor().newInstance();
    }
}
