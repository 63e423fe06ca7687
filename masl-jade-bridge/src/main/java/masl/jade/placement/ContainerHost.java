package masl.jade.placement;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.TickerBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import jade.wrapper.AgentController;
import jade.wrapper.StaleProxyException;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.jade.DfEntries;
import masl.jade.MessagesButTheDfs;
import masl.jade.PrimitiveTable;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.acl.Conversations;
import masl.jade.acl.JsonContent;
import masl.jade.acl.PlacementContent;
import masl.jade.acl.Reply;
import masl.jade.deployment.DeployedTeam;
import masl.jade.platform.JadeException;
import masl.jade.trust.MissionChannel;
import masl.jade.trust.MissionSecret;
import masl.runtime.AgentClasses;
import masl.runtime.AgentImplementation;
import masl.runtime.descriptor.AgentType;

/**
 * The agent of a container that hosts bodies ({@link MaslContainer}), named
 * {@code masl-container-NAME} and registered with the DF as {@value DfEntries#CONTAINER_SERVICE}
 * {@code NAME}. It obeys the platform's {@value Conversations#COORDINATOR} only, and only control
 * messages signed with the mission's secret ({@link MissionSecret}); any other is refused, said in
 * one line, and changes nothing. {@value Conversations#PLACE} (once) creates the bodies of
 * the agents placed here ({@link BodyAgent}; {@code INFORM} once they exist and are registered,
 * {@code FAILURE} with the reason otherwise), {@value Conversations#END} deletes them, answers,
 * and ends the container's mission. Shared events ({@code INFORM} {@value Conversations#EVENT})
 * go to the container's listener. It watches that the mission's coordinator (before one places
 * bodies here: the platform's AMS) can still be reached ({@value Conversations#ALIVE}): once a message to it
 * comes back undeliverable, it deletes the bodies and ends the container's mission, saying why
 * ({@link #lost()}).
 */
final class ContainerHost extends Agent {
    private static final long serialVersionUID = 1L;
    private static final long BODIES_TIMEOUT_SECONDS = 30;
    /** How often the container checks that its coordinator (or the AMS) can still be reached. */
    private static final long ALIVE_PERIOD_MILLIS = 500;
    private final transient String containerName;
    private final transient Function<String, AgentType> types;
    private final transient ClassLoader classes;
    private final transient Consumer<ACLMessage> events;
    private final transient MissionChannel channel;
    private final transient Consumer<String> refusals;
    private final transient CountDownLatch ready = new CountDownLatch(1);
    private final transient CountDownLatch ended = new CountDownLatch(1);
    /** Down once the bodies are placed here, or the mission ended before they were. */
    private final transient CountDownLatch settled = new CountDownLatch(1);
    private final transient List<AgentController> controllers = new ArrayList<>();
    private final transient List<BodyAgent> bodies = new ArrayList<>();
    private transient ExecutorService primitiveThreads;
    private final transient List<String> hosted = new CopyOnWriteArrayList<>();
    /** The one agent whose control messages this container obeys: the platform's {@value Conversations#COORDINATOR}. */
    private transient AID coordinator;
    private transient volatile boolean placed;
    /** Whether the bodies placed here exist and are registered. */
    private transient volatile boolean bodiesReady;
    private transient volatile String lost;
    /** Whether JADE deleted this agent: as its container ends (closed, or by its platform's shutdown), or alone. */
    private transient volatile boolean takenDown;
    private transient volatile String unhosted;
    /** Translates the programs of agents deployed here; null if this container runs none. */
    private final transient ProgramTranslator translator;
    /** The deployed agents' programs, once a placement deployed some here. */
    private transient volatile DeployedTeam team;

    /**
     * @param secretSource the mission's secret, asked for until a control message bears its signature
     * @param refusals     told one line for each control message refused (not from the coordinator with
     *                     the mission's secret), on this agent's thread
     */
    ContainerHost(String containerName, Function<String, AgentType> types, ClassLoader classes,
            Consumer<ACLMessage> events, MissionSecret.Source secretSource, Consumer<String> refusals,
            ProgramTranslator translator) {
        this.translator = translator;
        this.containerName = containerName;
        this.types = types;
        this.classes = classes;
        this.events = events;
        this.channel = MissionChannel.reading(Conversations.containerAgent(containerName), secretSource);
        this.refusals = refusals;
    }

    @Override
    protected void setup() {
        coordinator = new AID(Conversations.COORDINATOR, AID.ISLOCALNAME);
        try {
            DFService.register(this, DfEntries.service(getAID(), DfEntries.CONTAINER_SERVICE, containerName));
        } catch (FIPAException e) {
            throw new JadeException("the DF refused to register container " + containerName, e);
        }
        addBehaviour(new MessagesButTheDfs(this, this::take));
        addBehaviour(new TickerBehaviour(this, ALIVE_PERIOD_MILLIS) {
            private static final long serialVersionUID = 1L;

            @Override
            protected void onTick() {
                if (ended.getCount() > 0) {
                    send(aliveCheck());
                }
            }
        });
        ready.countDown();
    }

    private ACLMessage aliveCheck() {
        ACLMessage check = new ACLMessage(ACLMessage.INFORM);
        check.setConversationId(Conversations.ALIVE);
        check.addReceiver(placed ? coordinator : getAMS());
        return check;
    }

    /**
     * JADE deletes this agent when its container closes: {@link MaslContainer#close}, or the platform
     * shutting down (its main container ends and takes every container with it). In the latter case
     * the mission has not ended for this container: it ends now, lost with its platform, so that
     * whoever waits for its end (a container never placed, too) is let go.
     */
    @Override
    protected void takeDown() {
        takenDown = true;
        if (ended.getCount() > 0) {
            lost = "the platform is gone (its main container shut down)";
            endMission();
        }
        stopTeam(lost == null ? "the container closed" : lost);
        deleteBodies();
        try {
            DFService.deregister(this);
        } catch (FIPAException e) {
            // The platform is going away with its DF.
        }
    }

    boolean takenDown() {
        return takenDown;
    }

    CountDownLatch ready() {
        return ready;
    }

    CountDownLatch ended() {
        return ended;
    }

    /** The mission ended for this container: whoever waits for its bodies or its end is let go. */
    private void endMission() {
        ended.countDown();
        settled.countDown();
    }

    CountDownLatch settled() {
        return settled;
    }

    boolean bodiesReady() {
        return bodiesReady;
    }

    /** Why the mission ended without the coordinator saying so: its coordinator or the platform is gone; null if not. */
    String lost() {
        return lost;
    }

    /** Why this container could not create the bodies the coordinator placed here; null if it could, or has not been asked. */
    String unhosted() {
        return unhosted;
    }

    /** The mission's secret, once a control message confirmed it; null before. */
    MissionSecret secret() {
        return channel.secret();
    }

    /** The names of the bodies the coordinator placed here. */
    List<String> hosted() {
        return List.copyOf(hosted);
    }

    private void take(ACLMessage message) {
        if (message.getSender() != null && message.getSender().equals(getAMS())) {
            // The AMS says a message to the coordinator (a check, a deployed agent's) was undeliverable;
            // it is never answered, lest it answer back.
            boolean toCoordinator = Conversations.ALIVE.equals(message.getConversationId())
                    || Conversations.DEPLOYED.equals(message.getConversationId());
            if (message.getPerformative() == ACLMessage.FAILURE && toCoordinator && ended.getCount() > 0) {
                lost = placed ? "the mission's coordinator is gone (its JVM died or it left the platform)"
                        : "the platform's main container is gone";
                stopTeam(lost);
                deleteBodies();
                endMission();
            }
        } else if (isControl(message)) {
            String refusal = refusal(message);
            if (refusal != null) {
                refuse(message, refusal, false);
            } else {
                obey(message);
            }
        } else if (message.getPerformative() != ACLMessage.NOT_UNDERSTOOD) {
            send(AclInvocations.notUnderstood(message, new ContentException(
                    "a MASL container answers its mission's coordinator only")));
        }
    }

    private static boolean isControl(ACLMessage message) {
        String conversation = message.getConversationId();
        return message.getPerformative() == ACLMessage.REQUEST && (Conversations.PLACE.equals(conversation)
                || Conversations.END.equals(conversation) || Conversations.ALIVE.equals(conversation))
                || message.getPerformative() == ACLMessage.INFORM && (Conversations.EVENT.equals(conversation)
                        || Conversations.DEPLOYED.equals(conversation));
    }

    /** A control message that passed {@link #refusal}: placement (once), end, a check, or an event. */
    private void obey(ACLMessage message) {
        switch (message.getConversationId()) {
            case Conversations.PLACE -> {
                if (placed) {
                    refuse(message, "this container already hosts its mission's bodies", true);
                } else {
                    placed = true;
                    send(channel.sign(place(message), getAID()));
                    if (unhosted != null) {
                        endMission();
                    }
                }
            }
            case Conversations.DEPLOYED -> {
                DeployedTeam deployed = team;
                if (deployed == null) {
                    refuse(message, "no agent is deployed here", true);
                } else {
                    try {
                        deployed.receive(DeployedTeams.read(message.getContent()));
                    } catch (IllegalArgumentException malformed) {
                        refuse(message, malformed.getMessage(), true);
                    }
                }
            }
            case Conversations.END -> {
                stopTeam("the mission has ended");
                deleteBodies();
                send(channel.sign(AclInvocations.reply(message, Reply.Kind.RESULT, JsonContent.result(null)), getAID()));
                endMission();
            }
            case Conversations.ALIVE -> send(channel.sign(AclInvocations.reply(message, Reply.Kind.RESULT, JsonContent.result(null)),
                    getAID()));
            default -> events.accept(message);
        }
    }

    /**
     * Why a control message is not obeyed: not from the coordinator, not signed with the mission's
     * secret (JADE lets any agent write any sender; the signature no one without the secret can make),
     * or a copy of one already taken (an agent of the platform can see messages and send them again);
     * null if it is to be obeyed.
     */
    private String refusal(ACLMessage message) {
        if (!coordinator.equals(message.getSender())) {
            return "only " + Conversations.COORDINATOR + " controls a MASL container";
        }
        return channel.refusal(message);
    }

    /**
     * Answers a control message that is not obeyed ({@code REFUSE}, or {@code NOT_UNDERSTOOD} for an
     * event), said in one line; signed if the message proved to come from the coordinator
     * ({@code proven}), which acts on no unsigned answer, so that it learns why.
     */
    private void refuse(ACLMessage message, String reason, boolean proven) {
        refusals.accept("refused " + message.getConversationId() + " from "
                + (message.getSender() == null ? "no sender" : message.getSender().getName()) + ": " + reason);
        ACLMessage answer = message.getPerformative() == ACLMessage.REQUEST
                ? AclInvocations.reply(message, Reply.Kind.REFUSED, JsonContent.refusal(reason))
                : AclInvocations.notUnderstood(message, new ContentException(reason));
        send(proven ? channel.sign(answer, getAID()) : answer);
    }

    /**
     * Creates the bodies a placement names and answers {@code INFORM}; or deletes those made, answers
     * {@code FAILURE} with what went wrong and keeps it in {@link #unhosted}: the mission cannot run.
     */
    private ACLMessage place(ACLMessage request) {
        List<PlacementContent.Body> placed = List.of();
        List<String> deployedNames = List.of();
        try {
            placed = PlacementContent.read(request.getContent());
            primitiveThreads = Executors.newCachedThreadPool(runnable -> {
                Thread thread = new Thread(runnable, "masl-body-primitive");
                thread.setDaemon(true);
                return thread;
            });
            CountDownLatch registered = new CountDownLatch(placed.size());
            for (PlacementContent.Body body : placed) {
                BodyAgent agent = body(body, request, registered);
                AgentController controller = getContainerController().acceptNewAgent(body.name(), agent);
                controllers.add(controller);
                bodies.add(agent);
                hosted.add(body.name());
                controller.start();
            }
            if (!registered.await(BODIES_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                throw new JadeException("the bodies did not start within " + BODIES_TIMEOUT_SECONDS + " s");
            }
            for (BodyAgent agent : bodies) {
                if (agent.registrationFailure() != null) {
                    throw new JadeException("the DF refused to register " + agent.getLocalName());
                }
            }
            Optional<PlacementContent.Deploy> deploy = PlacementContent.readDeploy(request.getContent());
            if (deploy.isPresent()) {
                deployedNames = deploy.get().agents();
                team = DeployedTeams.make(deploy.get(), translator, containerName, message -> send(channel.sign(
                        Conversations.inform(coordinator, Conversations.DEPLOYED, message.toString()), getAID())));
                hosted.addAll(deployedNames);
            }
            bodiesReady = true;
            settled.countDown();
            return AclInvocations.reply(request, Reply.Kind.RESULT, JsonContent.result(null));
        } catch (ContentException | StaleProxyException | ReflectiveOperationException | RuntimeException
                | LinkageError | ProgramTranslator.Refusal problem) {
            deleteBodies();
            List<String> names = new ArrayList<>(placed.stream().map(PlacementContent.Body::name).toList());
            names.addAll(deployedNames);
            unhosted = Distribution.cannotHost(containerName, names, problem.getMessage());
            return AclInvocations.reply(request, Reply.Kind.FAILED, JsonContent.failure(problem));
        } catch (InterruptedException closing) {
            // JADE interrupts this agent's thread when its container closes (masl container's own timeout).
            Thread.currentThread().interrupt();
            return AclInvocations.reply(request, Reply.Kind.FAILED,
                    JsonContent.failure(new JadeException("the container closed before its bodies were placed")));
        }
    }

    private BodyAgent body(PlacementContent.Body body, ACLMessage request, CountDownLatch registered)
            throws ReflectiveOperationException {
        AgentType type = types.apply(body.className());
        AgentImplementation implementation;
        try {
            implementation = AgentClasses.instantiate(body.className(), classes);
        } catch (AgentClasses.CreationFailed thrown) {
            throw new JadeException("class " + body.className() + ": " + thrown.getMessage());
        }
        BodyJournal journal = new BodyJournal(body.proxyId());
        implementation.bind(journal);
        return new BodyAgent(implementation, journal, new PrimitiveTable(type, implementation.getClass()),
                coordinator, MissionChannel.of(body.name(), channel.secret()), primitiveThreads, registered);
    }

    /** Stops the deployed agents' steps, if any run here; the line saying why is the caller's. */
    private void stopTeam(String why) {
        DeployedTeam deployed = team;
        if (deployed != null) {
            deployed.lose(why);
        }
    }

    /** Deletes the bodies and waits, bounded, until their threads have ended; stops their primitives' threads. */
    private void deleteBodies() {
        for (AgentController controller : controllers) {
            try {
                controller.kill();
            } catch (StaleProxyException alreadyGone) {
                // Deleted already: the platform is shutting down.
            }
        }
        try {
            for (BodyAgent body : bodies) {
                Thread thread = body.thread();
                if (thread != null && thread != Thread.currentThread()) {
                    thread.join(TimeUnit.SECONDS.toMillis(BODIES_TIMEOUT_SECONDS));
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        controllers.clear();
        bodies.clear();
        if (primitiveThreads != null) {
            primitiveThreads.shutdownNow();
        }
    }
}
