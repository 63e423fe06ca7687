package masl.jade.deployment;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.scheduling.ThreadPerAgentScheduler;
import masl.runtime.testing.TestAgent;

/**
 * A mission whose named agents are deployed to a container in this JVM: the mission and the
 * container are joined by two wires that carry each message as JSON text, in order, on a thread of
 * their own, as JADE would. Each side makes its own program from {@code program}, as two JVMs that
 * translated the same source would.
 */
public final class InMemoryDeployment {

    private static final ObjectMapper JSON = new ObjectMapper();

    private InMemoryDeployment() {
    }

    /** How the mission ended, and how many messages went from the container to the mission. */
    public record Run(MissionOutcome outcome, int messagesFromContainer) {
    }

    public static Run run(Supplier<MissionProgram> program, Set<String> deployed, Duration timeout)
            throws InterruptedException {
        AtomicInteger messages = new AtomicInteger();
        ExecutorService toContainer = Executors.newSingleThreadExecutor();
        ExecutorService toMission = Executors.newSingleThreadExecutor();
        AtomicReference<Coordination> mission = new AtomicReference<>();
        AtomicReference<Mission> running = new AtomicReference<>();
        try (DeployedTeam team = new DeployedTeam(program.get(), deployed, spec -> new TestAgent(),
                message -> {
                    messages.incrementAndGet();
                    toMission.execute(() -> mission.get().receive(overTheWire(message)));
                })) {
            MissionProgram here = program.get();
            Coordination coordination = new Coordination(Coordination.mainOf(program.get(),
                    spec -> new TestAgent()), proxyId -> message -> toContainer.execute(
                            () -> team.receive(overTheWire(message))), text -> running.get().journal().append(text));
            mission.set(coordination);
            List<String> names = here.agents().stream().map(MissionProgram.AgentSpec::name).toList();
            List<AgentImplementation> created = new ArrayList<>();
            Mission.Builder builder = Mission.builder().scheduler(new ThreadPerAgentScheduler())
                    .programs((name, own) -> deployed.contains(name)
                            ? coordination.standIn(names.indexOf(name), own) : own);
            here.configure(builder, spec -> {
                TestAgent agent = new TestAgent();
                created.add(agent);
                return agent;
            });
            running.set(builder.build());
            coordination.agents(created);
            return new Run(running.get().run(timeout), messages.get());
        } finally {
            toContainer.shutdownNow();
            toMission.shutdownNow();
        }
    }

    private static ObjectNode overTheWire(ObjectNode message) {
        try {
            return (ObjectNode) JSON.readTree(JSON.writeValueAsString(message));
        } catch (JsonProcessingException impossible) {
            throw new IllegalStateException(impossible);
        }
    }
}
