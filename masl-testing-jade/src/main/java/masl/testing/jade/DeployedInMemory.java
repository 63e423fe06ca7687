package masl.testing.jade;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;
import masl.jade.deployment.Batch;
import masl.jade.deployment.Coordination;
import masl.jade.deployment.StandInsOnAPool;
import masl.jade.deployment.DeployedTeam;
import masl.jade.deployment.Wire;
import masl.runtime.AgentImplementation;
import masl.runtime.DeployedPrograms;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentType;
import masl.runtime.scheduling.ThreadPerAgentScheduler;
import masl.runtime.trace.Trace;
import masl.testing.MissionPlatform;
import masl.testing.TranslatedMission;

/**
 * Runs missions under test with agents' programs deployed ({@code masl run --deploy}) to containers
 * in this JVM, without JADE: the mission and each container are joined by two wires that carry each
 * message as JSON text, in order, on a thread of their own, as JADE would. Each side makes its own
 * program and agents' objects, as two JVMs that translated the same source would; the containers'
 * programs run against the deployed agents' remote context, the mission decides.
 *
 * <pre>{@code
 * MaslMission.fromString("labels.masl", source).runOn(DeployedInMemory.spread()).assertJournal("…");
 * }</pre>
 */
public final class DeployedInMemory implements MissionPlatform {

    private static final ObjectMapper JSON = new ObjectMapper();

    private final Function<List<String>, Map<String, String>> deployment;
    private final String named;

    private DeployedInMemory(Function<List<String>, Map<String, String>> deployment, String named) {
        this.deployment = deployment;
        this.named = named;
    }

    /** Every agent's program in one container, {@code c2}. */
    public static DeployedInMemory everyAgent() {
        return new DeployedInMemory(names -> inTurn(names, List.of("c2")), "every agent to c2");
    }

    /** Every agent's program, over two containers in turn ({@code --deploy '*=c2+c3'}). */
    public static DeployedInMemory spread() {
        return new DeployedInMemory(names -> inTurn(names, List.of("c2", "c3")), "every agent to c2+c3");
    }

    /** The programs of the agents {@code names} in container {@code c2}, the others' in the mission's JVM. */
    public static DeployedInMemory agents(String... names) {
        Map<String, String> deployed = new LinkedHashMap<>();
        for (String name : names) {
            deployed.put(name, "c2");
        }
        return new DeployedInMemory(all -> deployed, String.join(", ", names) + " to c2");
    }

    private static Map<String, String> inTurn(List<String> names, List<String> containers) {
        Map<String, String> deployed = new LinkedHashMap<>();
        for (String name : names) {
            deployed.put(name, containers.get(deployed.size() % containers.size()));
        }
        return deployed;
    }

    /**
     * How a mission ended, how many messages went from the containers to the mission and back, and how
     * many of each kind went either way, each message a batch combines counted ({@code "run"}: code a
     * container is asked to run; {@code "ran"}: its answer).
     */
    public record Run(MissionOutcome outcome, int messagesFromContainers, int messagesToContainers,
            Map<String, Integer> kinds) {
    }

    @Override
    public MissionOutcome run(TranslatedMission mission, Trace trace, Duration timeout) throws InterruptedException {
        List<String> names = mission.loader().program().agents().stream().map(MissionProgram.AgentSpec::name).toList();
        // The types the translation gave the agents, as each side makes them.
        List<AgentType> types = DeployedPrograms.outsideAMission(mission.loader().program(),
                mission.loader()::newImplementation).types();
        return run(mission.loader()::program, deployment.apply(names), mission.loader()::newImplementation,
                spec -> types.get(names.indexOf(spec.name())), trace, timeout).outcome();
    }

    /**
     * The wires between a mission and its containers, which a test may cut while the mission runs, as
     * the death of a container's JVM does: nothing goes either way any more, and the mission learns
     * that the container is gone, as its coordinator would from JADE.
     */
    public static final class Wires {
        private final Set<String> cut = ConcurrentHashMap.newKeySet();
        private volatile Consumer<String> lose = container -> { };
        private volatile Mission mission;

        /** The mission these wires join to its containers, once it is made (before it runs); else null. */
        public Mission mission() {
            return mission;
        }

        /** Cuts the wires of {@code container}; its agents fail with a cause naming it. */
        public void cut(String container) {
            cut.add(container);
            lose.accept(container);
        }

        private boolean carry(String container) {
            return !cut.contains(container);
        }
    }

    /**
     * Runs a mission of {@code program} (called once for each side) whose agents {@code containerOfAgent}
     * names run their programs in those containers, each joined to the mission by wires of its own;
     * every side makes the agents' objects with {@code implementations}, of the types {@code types} gives.
     */
    public static Run run(Supplier<MissionProgram> program, Map<String, String> containerOfAgent,
            MissionProgram.ImplementationFactory implementations, Function<MissionProgram.AgentSpec, AgentType> types,
            Trace trace, Duration timeout) throws InterruptedException {
        return run(program, containerOfAgent, implementations, types, trace, new Wires(), timeout);
    }

    /** Runs a mission as {@link #run(Supplier, Map, MissionProgram.ImplementationFactory, Function, Trace, Duration)}, over {@code wires}. */
    public static Run run(Supplier<MissionProgram> program, Map<String, String> containerOfAgent,
            MissionProgram.ImplementationFactory implementations, Function<MissionProgram.AgentSpec, AgentType> types,
            Trace trace, Wires wires, Duration timeout) throws InterruptedException {
        AtomicInteger messages = new AtomicInteger();
        AtomicInteger answers = new AtomicInteger();
        Map<String, Integer> kinds = new ConcurrentHashMap<>();
        ExecutorService toMission = Executors.newSingleThreadExecutor();
        AtomicReference<Coordination> mission = new AtomicReference<>();
        AtomicReference<Mission> running = new AtomicReference<>();
        Map<String, DeployedTeam> teams = new HashMap<>();
        Map<String, ExecutorService> toContainers = new HashMap<>();
        Map<String, Wire> wireOf = new HashMap<>();
        try {
            for (String container : new TreeSet<>(containerOfAgent.values())) {
                Set<String> here = new HashSet<>();
                containerOfAgent.forEach((agent, of) -> {
                    if (of.equals(container)) {
                        here.add(agent);
                    }
                });
                teams.put(container, new DeployedTeam(program.get(), here, implementations, message -> {
                    messages.incrementAndGet();
                    countKinds(message, kinds);
                    if (wires.carry(container)) {
                        toMission.execute(() -> mission.get().receive(overTheWire(message)));
                    }
                }));
                ExecutorService toContainer = Executors.newSingleThreadExecutor();
                toContainers.put(container, toContainer);
                // One wire per container, as over JADE: its agents' messages go together.
                wireOf.put(container, message -> {
                    answers.incrementAndGet();
                    countKinds(message, kinds);
                    if (wires.carry(container)) {
                        toContainer.execute(() -> teams.get(container).receive(overTheWire(message)));
                    }
                });
            }
            MissionProgram here = program.get();
            List<String> names = here.agents().stream().map(MissionProgram.AgentSpec::name).toList();
            Coordination coordination = new Coordination(Coordination.mainOf(program.get(), implementations),
                    proxyId -> wireOf.get(containerOfAgent.get(names.get(proxyId))),
                    text -> running.get().journal().append(text));
            mission.set(coordination);
            List<AgentImplementation> created = new ArrayList<>();
            Mission.Builder builder = Mission.builder()
                    .scheduler(new StandInsOnAPool(new ThreadPerAgentScheduler(), coordination)).trace(trace)
                    .programs((name, own) -> containerOfAgent.containsKey(name)
                            ? coordination.standIn(names.indexOf(name), own) : own);
            here.configure(builder, spec -> {
                AgentImplementation agent = coordination.implementationOf(created.size(), types.apply(spec),
                        implementations.create(spec), containerOfAgent.containsKey(spec.name()));
                created.add(agent);
                return agent;
            });
            running.set(builder.build());
            wires.mission = running.get();
            coordination.agents(running.get(), created);
            wires.lose = container -> coordination.lose(names.stream().filter(name -> container.equals(
                    containerOfAgent.get(name))).map(names::indexOf).toList(), "the container " + container + " is gone");
            MissionOutcome outcome = running.get().run(timeout);
            return new Run(outcome, messages.get(), answers.get(), Map.copyOf(kinds));
        } finally {
            teams.values().forEach(DeployedTeam::close);
            toContainers.values().forEach(ExecutorService::shutdownNow);
            toMission.shutdownNow();
        }
    }

    /** Counts the kind of {@code message}, or of each message of a batch. */
    private static void countKinds(ObjectNode message, Map<String, Integer> kinds) {
        Batch.each(message).forEach(inner -> kinds.merge(inner.path("kind").asText(), 1, Integer::sum));
    }

    private static ObjectNode overTheWire(ObjectNode message) {
        try {
            return (ObjectNode) JSON.readTree(JSON.writeValueAsString(message));
        } catch (JsonProcessingException impossible) {
            throw new IllegalStateException(impossible);
        }
    }

    @Override
    public String toString() {
        return "deployed in memory (" + named + ")";
    }
}
