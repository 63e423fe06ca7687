package masl.jade.placement;

import com.fasterxml.jackson.databind.node.ObjectNode;
import jade.core.AID;
import jade.core.Agent;
import jade.lang.acl.ACLMessage;
import jade.wrapper.AgentController;
import jade.wrapper.StaleProxyException;
import java.lang.reflect.Method;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import masl.jade.Answers;
import masl.jade.JadeLauncher;
import masl.jade.PrimitiveTable;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.acl.Conversations;
import masl.jade.acl.JsonContent;
import masl.jade.acl.PlacementContent;
import masl.jade.deployment.ContainerLostException;
import masl.jade.deployment.Batch;
import masl.jade.deployment.Coordination;
import masl.jade.deployment.Wire;
import masl.jade.outside.OutsideCalls;
import masl.jade.platform.ContainerDepartures;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadePlatform;
import masl.jade.stub.StubClasses;
import masl.jade.trust.ContainerClaims;
import masl.jade.trust.MissionSecret;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.descriptor.AgentType;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * The coordinator's side of one mission whose agents are placed in several containers
 * ({@link JadeLauncher#place}): the {@link CoordinatorAgent}, a stub with its {@link RemoteBody} for
 * each agent placed away from the main container, the bodies' placement in their containers
 * ({@link ContainerHost}), the requests FIPA agents send to those bodies, shared events sent to
 * the bodies, and the end of the mission in every container. One mission; not thread-safe but
 * where said.
 *
 * <p>Public for {@link masl.jade.JadeLauncher}, which builds a mission spanning containers around it.
 */
public final class Distribution {

    /** How long the end of a mission waits for the containers it ended to leave the platform. */
    private static final Duration CONTAINERS_LEAVE_WITHIN = Duration.ofSeconds(10);
    private static final long LEAVING_POLL_MILLIS = 20;
    private static final long LEAVING_PROBE_MILLIS = 250;

    private final Map<String, String> containerOfAgent;
    private final Duration agentsTimeout;
    /** How long a placement waits for each container to join and prove it holds the secret. */
    private final Duration containersWithin;
    /** Told one line for each message refused and each claimant of a container that did not prove itself. */
    private final Consumer<String> problems;
    private final CoordinatorAgent coordinator;
    private final AgentController controller;
    /** Remote agents by proxy id, in proxy id order. */
    private final Map<Integer, Remote> remotes = new LinkedHashMap<>();
    private final StubClasses stubs = new StubClasses();
    /** The agent of each container that hosts bodies, once found; read by emitting agents' threads. */
    private final Map<String, AID> containers = new ConcurrentHashMap<>();
    private volatile Served served;
    /**
     * The containers that accepted what was placed in them: only their departure leaves calls to fail,
     * and is said. One that refused may end before its refusal is read; the refusal says why.
     */
    private final Set<String> hosting = ConcurrentHashMap.newKeySet();
    /** The containers found gone, each said once. */
    private final Set<String> goneContainers = ConcurrentHashMap.newKeySet();
    /** The containers running deployed agents found gone, each said once. */
    private final Set<String> goneDeployments = ConcurrentHashMap.newKeySet();
    /** Set once the mission has ended: containers leaving then are expected. */
    private volatile boolean ending;
    /** Down once the container of that name is known gone: the AMS's removal event, or an undeliverable request. */
    private final Map<String, CountDownLatch> departures = new ConcurrentHashMap<>();

    private record Remote(String name, String container, String className, RemoteBody body) {
    }

    /** The agents whose programs run in other containers, and what those make them from (MASL, not code). */
    private record Deployed(Map<String, String> containerOfAgent, DeployedSource source, Coordination coordination,
            List<String> names, List<String> containerById) {

        Deployed(Map<String, String> containerOfAgent, DeployedSource source, Coordination coordination,
                List<String> names) {
            this(containerOfAgent, source, coordination, names, names.stream().map(containerOfAgent::get).toList());
        }

        /** The container of agent {@code proxyId}'s program, or null for an agent not deployed or no agent. */
        String containerOf(int proxyId) {
            return proxyId >= 0 && proxyId < containerById.size() ? containerById.get(proxyId) : null;
        }

        List<String> agentsIn(String container) {
            return names.stream().filter(name -> container.equals(containerOfAgent.get(name))).toList();
        }
    }

    private volatile Deployed deployed = new Deployed(Map.of(), null, null, List.of());
    private final AtomicLong deployedMessages = new AtomicLong();
    private volatile ContainerTraffic traffic = new ContainerTraffic();
    /** The wire to each container running deployed agents, by container name. */
    private final Map<String, Wire> wires = new ConcurrentHashMap<>();
    /** Whether the containers hosting bodies or deployed agents are still there, once placed; null before. */
    private volatile ContainerWatch watch;

    /** What a relayed request needs: the mission, each agent's name, primitives and implementation, the time limit. */
    private record Served(Mission mission, List<String> names, List<PrimitiveTable> tables,
            List<AgentImplementation> implementations, OutsideCalls outside) {
    }

    /**
     * Starts the coordinator agent in {@code platform}'s container (the main container).
     *
     * @param problems told one line for each message refused as not coming from a party of the mission
     *
     * @throws JadeException if it cannot start (another mission spanning containers runs on the platform)
     */
    public Distribution(JadePlatform platform, Map<String, String> containerOfAgent, MissionSecret secret,
            Duration agentsTimeout, Duration containersWithin, Consumer<String> problems) throws InterruptedException {
        this.containerOfAgent = Map.copyOf(containerOfAgent);
        this.agentsTimeout = agentsTimeout;
        this.containersWithin = containersWithin;
        CountDownLatch ready = new CountDownLatch(1);
        this.problems = problems;
        coordinator = new CoordinatorAgent(secret, problems, ready, this::serveRelayed, this::containerRemoved,
                this::unreachable);
        try {
            controller = platform.container().acceptNewAgent(Conversations.COORDINATOR, coordinator);
            controller.start();
        } catch (StaleProxyException e) {
            throw new JadeException("cannot start " + Conversations.COORDINATOR
                    + " (does another mission spanning containers run on this platform?)", e);
        }
        if (!ready.await(agentsTimeout.toMillis(), TimeUnit.MILLISECONDS)) {
            throw new JadeException(Conversations.COORDINATOR + " did not start within " + agentsTimeout);
        }
    }

    /** The JADE agent whose threaded behaviours run the programs of the agents whose bodies are elsewhere. */
    public Agent coordinator() {
        return coordinator;
    }

    /** The container agent {@code agent} is placed in, or null for the main container. */
    public String containerOf(String agent) {
        return containerOfAgent.get(agent);
    }

    /**
     * The stand-in of agent {@code proxyId} placed in {@code container}: a stub of its
     * implementation class whose primitives are requests to its body.
     */
    public AgentImplementation stub(int proxyId, String name, String container, AgentType type,
            Class<? extends AgentImplementation> implementation) {
        List<Method> methods = new PrimitiveTable(type, implementation).methods();
        RemoteBody body = new RemoteBody(name, new AID(name, AID.ISLOCALNAME), methods, coordinator, () -> {
            traffic.sentTo(container);
            traffic.receivedFrom(container);
        });
        remotes.put(proxyId, new Remote(name, container, implementation.getName(), body));
        return stubs.instantiate(implementation, methods, body);
    }

    /**
     * Deploys the programs of the agents {@code containerOfAgent} names to those containers, which
     * translate {@code source} themselves ({@link #place} sends it): their steps there, coordinated by
     * {@code coordination} here. Call before {@link #place}.
     */
    public void deploy(Map<String, String> containerOfAgent, DeployedSource source, Coordination coordination,
            List<String> names) {
        deployed = new Deployed(Map.copyOf(containerOfAgent), source, coordination, List.copyOf(names));
        coordinator.deployedTo(this::takeDeployed);
    }

    /**
     * Counts into {@code counts} from now on the deployed agents' coordination messages, and the
     * requests to placed bodies and their answers.
     */
    public void countInto(ContainerTraffic counts) {
        this.traffic = counts;
    }

    /**
     * The wire to the container running agent {@code proxyId}'s program: signed {@code INFORM}s. The
     * same wire for every agent of a container, so that their messages may go together. Call once
     * {@link #deploy} has been.
     */
    public Wire wireTo(int proxyId) {
        Deployed deployment = deployed;
        return wires.computeIfAbsent(deployment.containerOf(proxyId),
                name -> message -> {
                    AID container = containers.get(name);
                    ACLMessage inform = Conversations.inform(container, Conversations.DEPLOYED, message.toString());
                    inform.setReplyWith(CoordinatorAgent.deployedReplyWith(container.getLocalName(),
                            deployedMessages.incrementAndGet()));
                    coordinator.postSigned(inform);
                    traffic.sentTo(name);
                });
    }

    /**
     * A coordination message from a container (signed: {@link CoordinatorAgent} checked it): taken
     * only from the container that proved itself the one of the agent it names; otherwise refused and
     * said. On the coordinator's JADE thread; never blocks.
     */
    private void takeDeployed(ACLMessage message) {
        Deployed deployment = deployed;
        ObjectNode json;
        try {
            json = DeployedTeams.read(message.getContent());
        } catch (IllegalArgumentException malformed) {
            coordinator.refuse(message, malformed.getMessage());
            return;
        }
        // A batch is taken whole or refused whole: each message in it must come from its agent's container.
        List<ObjectNode> messages = Batch.each(json);
        String from = null;
        for (int id : Coordination.agentsNamed(messages)) {
            String container = deployment.containerOf(id);
            // A wave names one container's agents: its sender is checked once, not once per agent.
            if (container != null && container.equals(from)) {
                continue;
            }
            AID proven = container == null ? null : containers.get(container);
            if (proven == null || !proven.equals(message.getSender())) {
                String agent = id >= 0 && id < deployment.names().size() ? deployment.names().get(id) : null;
                coordinator.refuse(message, agent == null ? "it names no deployed agent"
                        : "it does not come from the container of " + agent);
                return;
            }
            from = container;
        }
        if (from == null) {
            coordinator.refuse(message, "it names no deployed agent");
            return;
        }
        traffic.receivedFrom(from);
        deployment.coordination().receive(messages);
    }

    /**
     * Once the mission is built: gives the bodies' stand-ins its journal, lets the coordinator serve
     * the requests bodies relay, and has each container create its bodies (waiting, up to
     * {@code containersWithin}, for each container to join the platform and prove itself).
     *
     * @throws JadeException if a container does not join in time or cannot host its bodies
     */
    public void place(Mission mission, List<String> names, List<PrimitiveTable> tables,
            List<AgentImplementation> implementations, OutsideCalls outside) throws InterruptedException {
        remotes.values().forEach(remote -> remote.body().journal(mission.journal()));
        served = new Served(mission, names, tables, implementations, outside);
        Map<String, List<PlacementContent.Body>> byContainer = new LinkedHashMap<>();
        remotes.forEach((id, remote) -> byContainer.computeIfAbsent(remote.container(), c -> new ArrayList<>())
                .add(new PlacementContent.Body(remote.name(), id, remote.className())));
        Deployed deployment = deployed;
        deployment.containerOfAgent().values().forEach(container -> byContainer.computeIfAbsent(container,
                c -> new ArrayList<>()));
        for (Map.Entry<String, List<PlacementContent.Body>> placed : byContainer.entrySet()) {
            List<String> programs = deployment.agentsIn(placed.getKey());
            DeployedSource source = deployment.source();
            PlacementContent.Deploy deploy = programs.isEmpty() ? null : new PlacementContent.Deploy(programs,
                    source.programName(), source.programText(), source.descriptors(), source.key());
            ContainerClaims.Proven proven = new ContainerClaims(coordinator, coordinator::ask, coordinator::forget,
                    placed.getKey(), containersWithin, problems).place(PlacementContent.write(placed.getValue(), deploy));
            containers.put(placed.getKey(), proven.container());
            ACLMessage answer = proven.answer();
            if (answer.getPerformative() != ACLMessage.INFORM) {
                List<String> hosted = new ArrayList<>(placed.getValue().stream().map(PlacementContent.Body::name).toList());
                hosted.addAll(programs);
                throw new JadeException(cannotHost(placed.getKey(), hosted, JsonContent.failureMessage(answer.getContent())));
            }
            hosting.add(placed.getKey());
        }
        // Every container, cleanly closed or killed: a body in the middle of a call sends nothing either.
        watch = new ContainerWatch(coordinator, containers::values);
    }

    /** What both sides say when a container cannot create the bodies placed in it: the same line. */
    static String cannotHost(String container, List<String> bodies, String why) {
        return "container " + container + " cannot host " + (bodies.isEmpty() ? "its bodies" : String.join(", ", bodies))
                + ": " + why;
    }

    /**
     * The mission's trace, plus shared events sent as {@code INFORM}s (conversation
     * {@value Conversations#EVENT}, one signed message for each) to every container hosting bodies,
     * for its observers: {@code {"event": "go", "block": "main", "emitter": "leader", "message": "now"}}.
     */
    public Trace sendingEvents(Trace trace, List<String> names) {
        return event -> {
            trace.record(event);
            if (event instanceof TraceEvent.EventEmitted emitted && emitted.block() != null && !containers.isEmpty()) {
                // An event a FIPA agent raised has no emitter among the mission's agents.
                String content = JsonContent.event(emitted.event(), emitted.block(),
                        emitted.agent() == Mission.OUTSIDE ? null : names.get(emitted.agent()), emitted.message());
                for (AID container : containers.values()) {
                    ACLMessage inform = new ACLMessage(ACLMessage.INFORM);
                    inform.setConversationId(Conversations.EVENT);
                    inform.setLanguage(AclInvocations.LANGUAGE);
                    inform.setOntology(AclInvocations.ONTOLOGY);
                    inform.setContent(content);
                    inform.addReceiver(container);
                    coordinator.postSigned(inform);
                }
            }
        };
    }

    /**
     * Tells every container the mission has ended (each deletes its bodies, answers, and leaves the
     * platform), waits for their answers and then for those that obeyed to leave, each bounded, and
     * deletes the coordinator.
     *
     * <p>Waiting for them to leave keeps a container half-gone from meeting the platform's shutdown,
     * which the caller usually starts next: JADE 4.3's AMS then removes it a second time and prints
     * {@code NotFoundException: No container named c2 was found} with its stack trace.
     */
    public void end() throws InterruptedException {
        ending = true;
        if (watch != null) {
            watch.close();
        }
        Map<String, AID> ended = new LinkedHashMap<>();
        for (Map.Entry<String, AID> container : containers.entrySet()) {
            try {
                ACLMessage answer = await(Conversations.request(container.getValue(), Conversations.END, "{}"),
                        "container " + container.getKey() + " to end");
                if (answer.getPerformative() == ACLMessage.INFORM) {
                    ended.put(container.getKey(), container.getValue());
                }
            } catch (JadeException gone) {
                // It ended on its own, or its JVM is gone: nothing of it is left to end.
            }
        }
        long deadline = System.nanoTime() + CONTAINERS_LEAVE_WITHIN.toNanos();
        for (Map.Entry<String, AID> container : ended.entrySet()) {
            // Past the bound the platform's shutdown removes it: a stack trace printed at worst.
            awaitLeaving(container.getKey(), container.getValue(), deadline);
        }
        try {
            controller.kill();
        } catch (StaleProxyException alreadyGone) {
            // The platform is shutting down.
        }
        Thread thread = coordinator.thread();
        if (thread != null) {
            thread.join(agentsTimeout.toMillis());
        }
    }

    private ACLMessage await(ACLMessage request, String what) throws InterruptedException {
        try {
            return coordinator.ask(request).get(agentsTimeout.toMillis(), TimeUnit.MILLISECONDS);
        } catch (TimeoutException e) {
            throw new JadeException("waited " + agentsTimeout + " for " + what, e);
        } catch (ExecutionException e) {
            throw new JadeException(e.getCause().getMessage(), e.getCause());
        }
    }

    /**
     * A container hosting bodies left the platform (its JVM died, or ended before the mission did):
     * calls waiting for its bodies, and later ones, fail with {@link ContainerGoneException}, and so
     * do the requests to its container agent ({@code masl-end}); said once on standard error. On the
     * coordinator's JADE thread.
     */
    private void containerRemoved(String container) {
        departure(container).countDown();
        loseDeployed(container);
        List<String> agents = remotes.values().stream().filter(remote -> remote.container().equals(container))
                .map(Remote::name).toList();
        if (agents.isEmpty() || !goneContainers.add(container)) {
            return;
        }
        if (!ending && hosting.contains(container)) {
            // The departure itself may have been said already, from what JADE logged of it.
            System.err.println(ContainerDepartures.said(container)
                    ? "masl: calls to " + String.join(", ", agents) + ", whose container " + container
                            + " left, now fail with uncaught_exception"
                    : "masl: the container " + container + " is gone (its JVM ended or died): calls to "
                            + String.join(", ", agents) + " now fail with uncaught_exception");
        }
        Map<String, String> reasons = new LinkedHashMap<>();
        agents.forEach(agent -> reasons.put(agent, "the container " + container + " of agent " + agent + " is gone"));
        reasons.put(Conversations.containerAgent(container), "the container " + container + " is gone");
        coordinator.abandon(reasons);
    }

    /**
     * The agents deployed to {@code container}, now gone, fail (their steps, and the calls waiting
     * for it, throw {@link ContainerLostException}); the others go on. Said once on standard error.
     */
    private void loseDeployed(String container) {
        Deployed deployment = deployed;
        List<String> agents = deployment.agentsIn(container);
        if (agents.isEmpty() || !goneDeployments.add(container)) {
            return;
        }
        if (!ending && hosting.contains(container)) {
            // The departure itself may have been said already, from what JADE logged of it.
            System.err.println(ContainerDepartures.said(container)
                    ? "masl: the deployed agents " + String.join(", ", agents) + ", whose container " + container
                            + " left, fail"
                    : "masl: the container " + container + " is gone (its JVM ended or died): its deployed agents "
                            + String.join(", ", agents) + " fail");
        }
        deployment.coordination().lose(agents.stream().map(deployment.names()::indexOf).toList(),
                "the container " + container + " is gone (its JVM ended or died)");
    }

    /**
     * Waits until {@code container} has left the platform: the AMS reports it removed, or a request to its
     * agent comes back undeliverable. Asked again every {@value #LEAVING_POLL_MILLIS} ms: the AMS's
     * events do not reach every coordinator (one whose platform ran an earlier mission may miss them).
     */
    private void awaitLeaving(String container, AID host, long deadline) throws InterruptedException {
        CountDownLatch departure = departure(container);
        while (departure.getCount() > 0 && System.nanoTime() - deadline < 0) {
            // A container still there answers NOT_UNDERSTOOD; for a gone one the AMS answers FAILURE,
            // which the coordinator reports as unreachable (CoordinatorAgent.take).
            // One half-gone may answer nothing: asked again.
            CompletableFuture<ACLMessage> answer = coordinator.ask(Conversations.request(host, Conversations.ALIVE, "{}"));
            try {
                answer.get(LEAVING_PROBE_MILLIS, TimeUnit.MILLISECONDS);
            } catch (ExecutionException | TimeoutException noAnswer) {
                answer.cancel(false);
            }
            departure.await(LEAVING_POLL_MILLIS, TimeUnit.MILLISECONDS);
        }
    }

    private CountDownLatch departure(String container) {
        return departures.computeIfAbsent(container, name -> new CountDownLatch(1));
    }

    /** A request to {@code receiver} was undeliverable: if it is a body or a container agent, its container is gone. */
    private void unreachable(String receiver) {
        String container = containerOfAgent.get(receiver);
        if (container == null) {
            container = deployed.containerOfAgent().get(receiver);
        }
        if (container == null) {
            container = containers.keySet().stream().filter(name -> Conversations.containerAgent(name).equals(receiver))
                    .findFirst().orElse(null);
        }
        if (container != null) {
            containerRemoved(container);
        }
    }

    /**
     * A FIPA agent's request that a body relayed: filtered by the agent's state as an "other" when the
     * agent serves it, then run through its stub (so on its body) within the limit of calls from
     * outside the mission (past it, the call's wait ends; the primitive runs on in the body's JVM until
     * it returns); the answer goes back to the body, which forwards it. On the coordinator's JADE
     * thread; never blocks.
     */
    private void serveRelayed(ACLMessage relay) {
        Served mission = served;
        int id = mission == null ? -1 : mission.names().indexOf(relay.getSender().getLocalName());
        if (id < 0 || !remotes.containsKey(id)) {
            coordinator.postSigned(AclInvocations.notUnderstood(relay, new ContentException(
                    relay.getSender().getLocalName() + " is no body of this mission")));
            return;
        }
        PrimitiveTable.Call call;
        try {
            call = mission.tables().get(id).bind(AclInvocations.readRequest(relay));
        } catch (ContentException problem) {
            coordinator.postSigned(AclInvocations.notUnderstood(relay, problem));
            return;
        }
        String name = mission.names().get(id);
        String primitive = call.primitive().name();
        // Queued, never served inline: the primitive is a request to the body, whose answer this thread takes.
        mission.mission().submitInvocation(id, primitive,
                () -> coordinator.postSigned(mission.outside().answer(relay, call, mission.implementations().get(id), name)),
                () -> coordinator.postSigned(Answers.refusal(relay, name, primitive)));
    }
}
