package masl.jade;

import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import jade.wrapper.AgentController;
import jade.wrapper.StaleProxyException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.acl.JsonContent;
import masl.jade.acl.PlacementContent;
import masl.jade.acl.Reply;
import masl.runtime.AgentImplementation;
import masl.runtime.descriptor.AgentType;

/**
 * The agent of a container that hosts bodies ({@link MaslContainer}), named
 * {@code masl-container-NAME} and registered with the DF as {@value DfEntries#CONTAINER_SERVICE}
 * {@code NAME}. It answers the coordinator: {@value CoordinatorAgent#PLACE} creates the bodies of
 * the agents placed here ({@link BodyAgent}; {@code INFORM} once they exist and are registered,
 * {@code FAILURE} with the reason otherwise), {@value CoordinatorAgent#END} deletes them, answers,
 * and ends the container's mission. Shared events ({@code INFORM} {@value CoordinatorAgent#EVENT})
 * go to the container's listener.
 */
final class ContainerHost extends Agent {
    private static final long serialVersionUID = 1L;
    private static final long BODIES_TIMEOUT_SECONDS = 30;

    private final transient String containerName;
    private final transient Function<String, AgentType> types;
    private final transient ClassLoader classes;
    private final transient Consumer<ACLMessage> events;
    private final transient CountDownLatch ready = new CountDownLatch(1);
    private final transient CountDownLatch ended = new CountDownLatch(1);
    private final transient List<AgentController> controllers = new ArrayList<>();
    private final transient List<BodyAgent> bodies = new ArrayList<>();
    private transient ExecutorService primitiveThreads;
    private final transient List<String> hosted = new CopyOnWriteArrayList<>();

    ContainerHost(String containerName, Function<String, AgentType> types, ClassLoader classes,
            Consumer<ACLMessage> events) {
        this.containerName = containerName;
        this.types = types;
        this.classes = classes;
        this.events = events;
    }

    static String agentName(String containerName) {
        return "masl-container-" + containerName;
    }

    @Override
    protected void setup() {
        try {
            DFService.register(this, DfEntries.service(getAID(), DfEntries.CONTAINER_SERVICE, containerName));
        } catch (FIPAException e) {
            throw new JadeException("the DF refused to register container " + containerName, e);
        }
        addBehaviour(new MessagesButTheDfs(this, this::take));
        ready.countDown();
    }

    @Override
    protected void takeDown() {
        deleteBodies();
        try {
            DFService.deregister(this);
        } catch (FIPAException e) {
            // The platform is going away with its DF.
        }
    }

    CountDownLatch ready() {
        return ready;
    }

    CountDownLatch ended() {
        return ended;
    }

    /** The names of the bodies the coordinator placed here. */
    List<String> hosted() {
        return List.copyOf(hosted);
    }

    private void take(ACLMessage message) {
        if (message.getPerformative() == ACLMessage.REQUEST && CoordinatorAgent.PLACE.equals(message.getConversationId())) {
            send(place(message));
        } else if (message.getPerformative() == ACLMessage.REQUEST
                && CoordinatorAgent.END.equals(message.getConversationId())) {
            deleteBodies();
            send(AclInvocations.reply(message, Reply.Kind.RESULT, JsonContent.result(null)));
            ended.countDown();
        } else if (message.getPerformative() == ACLMessage.INFORM
                && CoordinatorAgent.EVENT.equals(message.getConversationId())) {
            events.accept(message);
        } else if (message.getPerformative() != ACLMessage.NOT_UNDERSTOOD) {
            send(AclInvocations.notUnderstood(message, new ContentException(
                    "a MASL container answers its mission's coordinator only")));
        }
    }

    private ACLMessage place(ACLMessage request) {
        try {
            List<PlacementContent.Body> placed = PlacementContent.read(request.getContent());
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
            return AclInvocations.reply(request, Reply.Kind.RESULT, JsonContent.result(null));
        } catch (ContentException | StaleProxyException | ReflectiveOperationException | RuntimeException
                | LinkageError problem) {
            deleteBodies();
            return AclInvocations.reply(request, Reply.Kind.FAILED, JsonContent.failure(problem));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return AclInvocations.reply(request, Reply.Kind.FAILED, JsonContent.failure(e));
        }
    }

    private BodyAgent body(PlacementContent.Body body, ACLMessage request, CountDownLatch registered)
            throws ReflectiveOperationException {
        AgentType type = types.apply(body.className());
        AgentImplementation implementation = Class.forName(body.className(), true, classes)
                .asSubclass(AgentImplementation.class).getConstructor().newInstance();
        BodyJournal journal = new BodyJournal(body.proxyId());
        implementation.bind(journal);
        return new BodyAgent(implementation, journal, new PrimitiveTable(type, implementation.getClass()),
                request.getSender(), primitiveThreads, registered);
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
