package masl.jade.deployment;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;
import masl.jade.TestPrograms;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.scheduling.ThreadPerAgentScheduler;

/**
 * A mission whose named agents are deployed to containers in this JVM: the mission and each
 * container are joined by two wires that carry each message as JSON text, in order, on a thread of
 * their own, as JADE would. Each side makes its own program from {@code program}, as two JVMs that
 * translated the same source would.
 */
public final class InMemoryDeployment {

    private static final ObjectMapper JSON = new ObjectMapper();

    private InMemoryDeployment() {
    }

    /** How the mission ended, and how many messages went from the containers to the mission and back. */
    public record Run(MissionOutcome outcome, int messagesFromContainer, int messagesToContainer) {
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
        AtomicInteger messages = new AtomicInteger();
        AtomicInteger answers = new AtomicInteger();
        ExecutorService toMission = Executors.newSingleThreadExecutor();
        AtomicReference<Coordination> mission = new AtomicReference<>();
        AtomicReference<Mission> running = new AtomicReference<>();
        Map<String, DeployedTeam> teams = new HashMap<>();
        Map<String, ExecutorService> toContainers = new HashMap<>();
        Map<String, Wire> wires = new HashMap<>();
        try {
            for (String container : new TreeSet<>(containerOfAgent.values())) {
                Set<String> here = new HashSet<>();
                containerOfAgent.forEach((agent, of) -> {
                    if (of.equals(container)) {
                        here.add(agent);
                    }
                });
                teams.put(container, new DeployedTeam(program.get(), here, InMemoryDeployment::newAgent, message -> {
                    messages.incrementAndGet();
                    toMission.execute(() -> mission.get().receive(overTheWire(message)));
                }));
                ExecutorService toContainer = Executors.newSingleThreadExecutor();
                toContainers.put(container, toContainer);
                // One wire per container, as over JADE: its agents' messages go together.
                wires.put(container, message -> {
                    answers.incrementAndGet();
                    toContainer.execute(() -> teams.get(container).receive(overTheWire(message)));
                });
            }
            MissionProgram here = program.get();
            List<String> names = here.agents().stream().map(MissionProgram.AgentSpec::name).toList();
            Coordination coordination = new Coordination(Coordination.mainOf(program.get(),
                    InMemoryDeployment::newAgent), proxyId -> wires.get(containerOfAgent.get(names.get(proxyId))),
                    text -> running.get().journal().append(text));
            mission.set(coordination);
            List<AgentImplementation> created = new ArrayList<>();
            Mission.Builder builder = Mission.builder().scheduler(new ThreadPerAgentScheduler())
                    .programs((name, own) -> containerOfAgent.containsKey(name)
                            ? coordination.standIn(names.indexOf(name), own) : own);
            here.configure(builder, spec -> {
                AgentImplementation agent = coordination.implementationOf(created.size(), TestPrograms.type(spec),
                        newAgent(spec), containerOfAgent.containsKey(spec.name()));
                created.add(agent);
                return agent;
            });
            running.set(builder.build());
            coordination.agents(created);
            return new Run(running.get().run(timeout), messages.get(), answers.get());
        } finally {
            teams.values().forEach(DeployedTeam::close);
            toContainers.values().forEach(ExecutorService::shutdownNow);
            toMission.shutdownNow();
        }
    }

    private static AgentImplementation newAgent(MissionProgram.AgentSpec spec) throws ReflectiveOperationException {
        return (AgentImplementation) Class.forName(spec.typeClassName()).getConstructor().newInstance();
    }

    private static ObjectNode overTheWire(ObjectNode message) {
        try {
            return (ObjectNode) JSON.readTree(JSON.writeValueAsString(message));
        } catch (JsonProcessingException impossible) {
            throw new IllegalStateException(impossible);
        }
    }
}
