package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.IntNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.LongNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.IntFunction;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;
import masl.runtime.DeployedPrograms;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.MissionProgram;
import masl.runtime.RemotePrimitiveException;
import masl.runtime.descriptor.AgentType;
import masl.runtime.scheduling.Blocking;

/**
 * The mission's side of its deployed agents: the one authority. Each deployed agent is a
 * {@link StandIn} in the mission, scheduled, parked, woken and watched as any agent; its steps run in
 * its container ({@link DeployedTeam}), whose requests the stand-in performs on the agent's context
 * here. Messages from containers come in through {@link #receive}, in the order each container sent
 * them: the journal text they carry is appended at once, before the request is performed. Messages to
 * a container wait in its {@link Outbox} until none of its agents waits for the mission any more.
 */
public final class Coordination {

    /** How often a thread waiting for a container looks whether it is gone. */
    private static final long LOST_POLL_MILLIS = 50;

    private final Blocks blocks;
    private final IntFunction<Wire> wireOf;
    private final Consumer<String> journal;
    private final ContextCalls calls = new ContextCalls(this);
    private final NamedCalls named = new NamedCalls(this);
    private final MissionLabels labels = new MissionLabels(this);
    private final WakeUps wakeUps = new WakeUps();
    private final Map<Integer, StandIn> standIns = new ConcurrentHashMap<>();
    /** The stand-ins by proxy id once the mission's agents are all made ({@link #agents}): read per message. */
    private volatile StandIn[] standInsById;
    private final Map<Long, Run> runs = new ConcurrentHashMap<>();
    private final AtomicLong runNumbers = new AtomicLong();

    /** A request to the container of {@code agent} waiting for its answer. */
    private record Run(int agent, CompletableFuture<ObjectNode> answer) {
    }

    /** Why each container is gone, by the proxy ids of its agents. */
    private final Map<Integer, String> lost = new ConcurrentHashMap<>();
    private volatile List<AgentImplementation> agents = List.of();
    private volatile Mission mission;
    /** The outbox of each deployed agent's container, by proxy id, and by wire. */
    private final Map<Integer, Outbox> outboxOf = new ConcurrentHashMap<>();
    private final Map<Wire, Outbox> outboxOfWire = new IdentityHashMap<>();

    /**
     * @param main the program's top-level block, as this JVM translated it
     * @param wireOf the wire to the container of each deployed agent, by proxy id: one wire per
     *     container, the same object for all its agents, whose messages go together ({@link Outbox})
     * @param journal where the deployed agents' journal text goes: the mission's journal
     */
    public Coordination(EntryDefinition main, IntFunction<Wire> wireOf, Consumer<String> journal) {
        this.blocks = new Blocks(main);
        this.wireOf = wireOf;
        this.journal = journal;
    }

    /**
     * The top-level block of {@code program}, as this JVM translated it: the one whose blocks the
     * containers' requests name. Makes the program's agents once more, with implementations from
     * {@code implementations} that serve no mission.
     */
    public static EntryDefinition mainOf(MissionProgram program, MissionProgram.ImplementationFactory implementations) {
        return outside(program, implementations).main();
    }

    /** The types of {@code program}'s agents by proxy id (null for one declared without), made as {@link #mainOf}. */
    static List<AgentType> typesOf(MissionProgram program, MissionProgram.ImplementationFactory implementations) {
        return outside(program, implementations).types();
    }

    private static DeployedPrograms.Made outside(MissionProgram program,
            MissionProgram.ImplementationFactory implementations) {
        TeamJournal nowhere = new TeamJournal();
        AtomicInteger next = new AtomicInteger();
        return DeployedPrograms.outsideAMission(program, spec -> {
            AgentImplementation implementation = implementations.create(spec);
            implementation.bind(nowhere.servicesOf(next.getAndIncrement()));
            return implementation;
        });
    }

    /** The program agent {@code proxyId} runs in the mission: a stand-in for {@code program}, which runs in its container. */
    public AgentProgram standIn(int proxyId, AgentProgram program) {
        StandIn standIn = new StandIn(proxyId, program, this);
        standIns.put(proxyId, standIn);
        return standIn;
    }

    /** Whether agent {@code proxyId}'s program is a stand-in's: its steps run in its container. */
    boolean isStandIn(int proxyId) {
        return standIns.containsKey(proxyId);
    }

    /**
     * The object agent {@code proxyId} has here, given the one {@code made} (its own class's, or its
     * placed body's or external agent's stub): {@code made}, or for a deployed agent a stub whose
     * primitives run in its container, on its real object. Binds the members of {@code type} that
     * invocations from deployed agents may name.
     */
    public AgentImplementation implementationOf(int proxyId, AgentType type, AgentImplementation made,
            boolean deployed) {
        return named.implementationOf(proxyId, type, made, deployed);
    }

    /**
     * The mission's agents' implementations, by proxy id: what requests naming agents mean here; and
     * the mission that runs them, which fails those whose container is lost.
     */
    public void agents(Mission mission, List<AgentImplementation> implementations) {
        this.agents = List.copyOf(implementations);
        StandIn[] byId = new StandIn[agents.size()];
        standIns.forEach((id, standIn) -> byId[id] = standIn);
        this.standInsById = byId;
        this.mission = mission;
        standIns.forEach((id, standIn) ->
                DeployedPrograms.onBoundaryWork(mission.agentOf(agents.get(id)), standIn::boundaryWork));
    }

    /**
     * A message from the container of the agents it names: a batch of requests and ends of steps, in
     * the order the container made them (or one of them).
     */
    public void receive(ObjectNode message) {
        receive(Batch.each(message));
    }

    /** The messages of a container's batch ({@link Batch#each}), in its order, as {@link #receive(ObjectNode)} takes them. */
    public void receive(List<ObjectNode> messages) {
        Mission running = mission;
        Runnable unpack = () -> {
            countWaiting(messages);
            messages.forEach(this::take);
        };
        // A wave's requests wake their stand-ins: the mission's threads are woken once for all.
        if (running == null) {
            unpack.run();
        } else {
            running.scheduler().together(unpack);
        }
    }

    /**
     * Every agent asking in {@code messages} waits for the mission from now on: counted before any is
     * answered, so that no answer goes alone; in one change per outbox, as a batch is one container's.
     */
    private void countWaiting(List<ObjectNode> messages) {
        Outbox counting = null;
        int waiting = 0;
        for (ObjectNode message : messages) {
            StandIn asking = waitsForTheMission(message);
            if (asking == null) {
                continue;
            }
            Outbox outbox = outbox(asking);
            if (outbox != counting) {
                if (counting != null) {
                    counting.busy(waiting);
                }
                counting = outbox;
                waiting = 0;
            }
            waiting++;
        }
        if (counting != null) {
            counting.busy(waiting);
        }
    }

    /**
     * The proxy ids each message from a container names, in order: one for a message, one per message
     * of a batch, and the callee too of an invocation the container says it served; -1 where none is
     * named. A container speaks only for its own agents: it vouches for both ends of such an invocation.
     */
    public static List<Integer> agentsNamed(ObjectNode message) {
        return agentsNamed(Batch.each(message));
    }

    /** The proxy ids the messages of a batch ({@link Batch#each}) name, as {@link #agentsNamed(ObjectNode)}. */
    public static List<Integer> agentsNamed(List<ObjectNode> messages) {
        List<Integer> named = new ArrayList<>();
        for (ObjectNode inner : messages) {
            named.add(inner.path("agent").asInt(-1));
            if ("invoked".equals(inner.path("kind").asText())) {
                named.add(inner.path("callee").asInt(-1));
            }
        }
        return named;
    }

    /** The stand-in of the agent {@code message} names if the message has it wait for the mission, else null. */
    private StandIn waitsForTheMission(JsonNode message) {
        String kind = message.path("kind").asText();
        // A step that ran code for the mission waits for the answer to its request again.
        boolean waits = "call".equals(kind) || "yield".equals(kind)
                || "ran".equals(kind) && message.path("inStep").booleanValue();
        return waits ? standIn(message.path("agent").intValue()) : null;
    }

    /** The stand-in of agent {@code proxyId}, or null if it runs no program deployed. */
    private StandIn standIn(int proxyId) {
        StandIn[] byId = standInsById;
        if (byId == null) {
            return standIns.get(proxyId);
        }
        return proxyId >= 0 && proxyId < byId.length ? byId[proxyId] : null;
    }

    private void take(ObjectNode message) {
        JsonNode written = message.get("journal");
        if (written != null) {
            journal.accept(written.textValue());
        }
        switch (message.path("kind").asText()) {
            case "call", "yield" -> {
                StandIn standIn = standIn(message.path("agent").intValue());
                if (standIn != null) {
                    standIn.requested(message);
                }
            }
            case "ran" -> {
                // Only the container asked answers: the agent it names is the one the run was for.
                long number = message.path("run").longValue();
                Run run = runs.get(number);
                if (run != null && run.agent() == message.path("agent").intValue() && runs.remove(number, run)) {
                    run.answer().complete(message);
                }
            }
            case "invoked" -> invokedInContainer(message);
            default -> throw new IllegalArgumentException("not a message of a deployed agent: " + message);
        }
    }

    /**
     * An invocation between two agents of one container, which that container served
     * ({@code InvocationsHere}): traced as the runtime traces one it serves. Both agents must be
     * deployed, to the container that sent it (the wire that carries it checked the sender).
     */
    private void invokedInContainer(ObjectNode record) {
        int requester = record.path("agent").asInt(-1);
        int callee = record.path("callee").asInt(-1);
        Mission running = mission;
        if (running == null || !standIns.containsKey(requester) || !standIns.containsKey(callee)
                || wireOf.apply(requester) != wireOf.apply(callee)) {
            throw new IllegalArgumentException("not an invocation between agents of one container: " + record);
        }
        DeployedPrograms.invokedElsewhere(running.agentOf(agents.get(requester)), running.agentOf(agents.get(callee)),
                record.path("primitive").asText(), record.path("pc").asInt());
    }

    /**
     * The container of the agents {@code proxyIds} is gone ({@code why}): those agents fail and the
     * others go on. A step in flight and a call waiting for the container throw; an agent whose step
     * is suspended in the mission (at a barrier, in a wait, a sleep, a blocked entry) is failed by
     * the mission now, which wakes it to die, so that nothing waits for it.
     */
    public void lose(List<Integer> proxyIds, String why) {
        proxyIds.forEach(id -> lost.put(id, why));
        Mission running = mission;
        if (running != null) {
            proxyIds.forEach(id -> running.agentOf(agents.get(id)).failFromOutside(new ContainerLostException(why)));
        }
    }

    Blocks blocks() {
        return blocks;
    }

    ContextCalls calls() {
        return calls;
    }

    NamedCalls named() {
        return named;
    }

    MissionLabels labels() {
        return labels;
    }

    WakeUps wakeUps() {
        return wakeUps;
    }

    List<AgentImplementation> agents() {
        return agents;
    }

    /**
     * Sends the message of number {@code seq} and fields {@code fields}, which must not change from
     * then on, to the container of {@code standIn}'s agent, which it lets go on.
     */
    void send(StandIn standIn, ObjectNode fields, long seq) {
        outbox(standIn).add(new Batch.Held(fields, IntNode.valueOf(standIn.id()), LongNode.valueOf(seq)), -1);
    }

    /**
     * Sends {@code message} to the container of {@code standIn}'s agent, whose step runs there: with
     * the others the outbox holds, at once if none of its agents waits for the mission.
     */
    void push(StandIn standIn, ObjectNode message) {
        outbox(standIn).add(message.put("agent", standIn.id()), 0);
    }

    /** The container of {@code standIn}'s agent no longer waits for the mission for it: it ended. */
    void ended(StandIn standIn) {
        outbox(standIn).busy(-1);
    }

    /** The outbox of {@code standIn}'s container, kept by the stand-in once named: it never changes. */
    private Outbox outbox(StandIn standIn) {
        Outbox outbox = standIn.outbox();
        if (outbox == null) {
            outbox = outbox(standIn.id());
            standIn.outbox(outbox);
        }
        return outbox;
    }

    /**
     * The outbox of agent {@code proxyId}'s container, one per wire. An agent waits for the mission
     * from the first time one is named here: for its first step, or for the end of a call run there.
     * The first use names every stand-in there is (once the mission runs, every one), so that the
     * first steps of a container's agents go together too.
     */
    private Outbox outbox(int proxyId) {
        Outbox outbox = outboxOf.get(proxyId);
        if (outbox != null) {
            return outbox;
        }
        synchronized (outboxOfWire) {
            if (outboxOf.isEmpty()) {
                standIns.keySet().forEach(this::waiting);
            }
            outbox = outboxOf.get(proxyId);
            return outbox != null ? outbox : waiting(proxyId);
        }
    }

    /** Agent {@code proxyId} waits for the mission in its container's outbox, made if need be; under the lock. */
    private Outbox waiting(int proxyId) {
        Outbox outbox = outboxOfWire.computeIfAbsent(wireOf.apply(proxyId), wire -> new Outbox(wire, 0));
        outbox.busy(1);
        outboxOf.put(proxyId, outbox);
        return outbox;
    }

    /**
     * The next message for a stand-in's step, waited for on the calling thread, which is the agent's
     * and may be a pool's ({@link Blocking}); throws once its container is gone.
     */
    ObjectNode await(int proxyId, StepMessages requests) {
        return blocking(proxyId, () -> {
            while (true) {
                ObjectNode request = requests.poll();
                if (request != null) {
                    return request;
                }
                try {
                    requests.arrival().get(LOST_POLL_MILLIS, TimeUnit.MILLISECONDS);
                } catch (TimeoutException notYet) {
                    failIfLost(proxyId);
                }
            }
        });
    }

    /** Runs {@code wait}, which blocks until it returns or agent {@code proxyId}'s container is gone, so that no pool starves. */
    private <T> T blocking(int proxyId, Callable<T> wait) {
        try {
            return Blocking.call(wait);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while agent " + proxyId + " ran in its container");
        } catch (ExecutionException impossible) {
            throw new IllegalStateException(impossible.getCause());
        } catch (RuntimeException failed) {
            throw failed;
        } catch (Exception impossible) {
            throw new IllegalStateException(impossible);
        }
    }

    private void failIfLost(int proxyId) {
        String why = lost.get(proxyId);
        if (why != null) {
            throw new ContainerLostException(why);
        }
    }

    /** Runs call {@code call} of agent {@code proxyId}'s program in its container: {@link ContextCalls#RAN}, or throws what it threw. */
    Object run(int proxyId, long call, JsonNode argument) {
        ask(proxyId, runOf(call, argument));
        return ContextCalls.RAN;
    }

    /** Applies the function {@code call} of agent {@code proxyId}'s program (a label's store) to {@code value} in its container: its result, as {@link Values} writes it. */
    JsonNode apply(int proxyId, long call, JsonNode value) {
        return ask(proxyId, runOf(call, value)).get("value");
    }

    private static ObjectNode runOf(long call, JsonNode argument) {
        ObjectNode run = JsonNodeFactory.instance.objectNode().put("kind", "run").put("call", call);
        if (argument != null) {
            run.set("argument", argument);
        }
        return run;
    }

    /**
     * Sends {@code request} to the container of agent {@code proxyId} and waits for its answer,
     * {@code ran}; throws what ran there threw, named as there, or once the container is gone.
     */
    ObjectNode ask(int proxyId, ObjectNode request) {
        long number = runNumbers.incrementAndGet();
        CompletableFuture<ObjectNode> answer = new CompletableFuture<>();
        runs.put(number, new Run(proxyId, answer));
        try {
            // The container runs it while the agent waits for the mission: it goes at once.
            outbox(proxyId).now(request.put("run", number).put("agent", proxyId));
            return outcome(awaitRun(proxyId, answer));
        } finally {
            runs.remove(number);
        }
    }

    /**
     * Has agent {@code proxyId}'s step, which waits in its container for the request being performed
     * on this thread, run the code {@code call} on {@code argument}: the step runs it, and the requests
     * it makes meanwhile (an initialiser's {@code main.count}) come to {@code standIn} to perform, as
     * in-process, where the runtime runs that code on the agent's thread. The answer completes the
     * future; the agent no longer waits for the mission until then.
     */
    CompletableFuture<ObjectNode> runInStep(int proxyId, long call, JsonNode argument) {
        long number = runNumbers.incrementAndGet();
        CompletableFuture<ObjectNode> answer = new CompletableFuture<>();
        runs.put(number, new Run(proxyId, answer));
        answer.whenComplete((ran, failed) -> runs.remove(number));
        Outbox outbox = outbox(proxyId);
        outbox.now(runOf(call, argument).put("inStep", true).put("run", number).put("agent", proxyId));
        outbox.busy(-1);
        return answer;
    }

    /** The answer {@code ran} of a run; throws what ran there threw, named as there. */
    static ObjectNode outcome(ObjectNode ran) {
        if (!"ran".equals(ran.path("outcome").asText())) {
            throw new RemotePrimitiveException(ran.path("class").asText(), ran.path("message").asText());
        }
        return ran;
    }

    private ObjectNode awaitRun(int proxyId, CompletableFuture<ObjectNode> answer) {
        return blocking(proxyId, () -> {
            while (true) {
                try {
                    return answer.get(LOST_POLL_MILLIS, TimeUnit.MILLISECONDS);
                } catch (TimeoutException notYet) {
                    failIfLost(proxyId);
                }
            }
        });
    }
}
