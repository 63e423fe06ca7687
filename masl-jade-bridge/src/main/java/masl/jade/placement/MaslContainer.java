package masl.jade.placement;

import jade.lang.acl.ACLMessage;
import jade.wrapper.StaleProxyException;
import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.jade.JadeLauncher;
import masl.jade.acl.Conversations;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.platform.Readiness;
import masl.jade.trust.MissionSecret;
import masl.runtime.descriptor.AgentType;

/**
 * A container that joins a platform to host the bodies of the MASL agents a mission places on it
 * ({@code masl container --main-host H --main-port P --name C}): the programs run in the
 * coordinator's JVM ({@link JadeLauncher#place}), the primitives here. It waits for the
 * coordinator, hosts the bodies it asks for, and its mission ends when the coordinator says so.
 * It serves one mission: close it once that has ended (and start another for the next mission). The coordinator's end of the mission waits
 * (up to 10 s) for the containers it ended to leave the platform.
 *
 * <pre>{@code
 * try (MaslContainer container = MaslContainer.start(JadeOptions.join(host, port), "c2",
 *         loader::loadByClassName, loader.implementationClasses(), event -> { },
 *         MissionSecret.Source.file(secretFile))) {
 *     container.awaitMissionEnd(Duration.ofMinutes(5));
 * }
 * }</pre>
 */
public final class MaslContainer implements AutoCloseable {

    private static final Duration START_TIMEOUT = Duration.ofSeconds(30);

    private final String name;
    private final JadePlatform platform;
    private final ContainerHost host;

    private MaslContainer(String name, JadePlatform platform, ContainerHost host) {
        this.name = name;
        this.platform = platform;
        this.host = host;
    }

    /**
     * Joins the platform as container {@code name} and waits for a coordinator. Control messages not
     * from the platform's coordinator signed with the mission's secret are refused, each said in one
     * line on standard error.
     *
     * @param types     the agent type of an implementation class name (its descriptor)
     * @param classes   where the implementation classes are loaded from
     * @param events    receives the shared events the coordinator sends this container ({@code INFORM},
     *                  conversation {@value Conversations#EVENT}), on the container agent's JADE thread
     * @param secret    the mission's secret, which the coordinator's {@link JadeLauncher#secret} has too;
     *                  asked for at each control message until one bears its signature
     * @throws JadeException if the container cannot join or its agent cannot start
     */
    public static MaslContainer start(JadeOptions joining, String name, Function<String, AgentType> types,
            ClassLoader classes, Consumer<ACLMessage> events, MissionSecret.Source secret) {
        return start(joining, name, types, classes, events, secret,
                refusal -> System.err.println("masl: container " + name + ": " + refusal));
    }

    /** As {@code start} above, each refusal said in one line to {@code refusals} (on the container agent's thread). */
    public static MaslContainer start(JadeOptions joining, String name, Function<String, AgentType> types,
            ClassLoader classes, Consumer<ACLMessage> events, MissionSecret.Source secret, Consumer<String> refusals) {
        return start(joining, name, types, classes, events, secret, refusals, null);
    }

    /**
     * As {@code start} above; the container also runs the programs of agents a coordinator deploys here
     * ({@link JadeLauncher#deploy}), translated by {@code translator} from the source the coordinator sends.
     */
    public static MaslContainer start(JadeOptions joining, String name, Function<String, AgentType> types,
            ClassLoader classes, Consumer<ACLMessage> events, MissionSecret.Source secret, Consumer<String> refusals,
            ProgramTranslator translator) {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(secret, "secret");
        JadePlatform platform = JadePlatform.start(joining.withContainerName(name));
        try {
            ContainerHost host = new ContainerHost(name, types, classes, events, secret, refusals, translator);
            platform.container().acceptNewAgent(Conversations.containerAgent(name), host).start();
            if (!host.ready().await(START_TIMEOUT.toMillis(), TimeUnit.MILLISECONDS)) {
                throw new JadeException("container " + name + " did not register within " + START_TIMEOUT);
            }
            return new MaslContainer(name, platform, host);
        } catch (StaleProxyException e) {
            platform.close();
            throw new JadeException("cannot start the agent of container " + name + " (is the name taken?)", e);
        } catch (InterruptedException e) {
            platform.close();
            Thread.currentThread().interrupt();
            throw new JadeException("interrupted while container " + name + " started", e);
        } catch (RuntimeException e) {
            platform.close();
            throw e;
        }
    }

    /**
     * Waits until the coordinator says the mission ended, or the container finds its coordinator
     * or the platform gone ({@link #lostPlatform()}); false if {@code timeout} elapsed first.
     */
    public boolean awaitMissionEnd(Duration timeout) throws InterruptedException {
        return host.ended().await(timeout.toMillis(), TimeUnit.MILLISECONDS);
    }

    /**
     * Waits until the coordinator has placed this container's bodies (and they are registered), or the
     * mission ended before it did; true if the bodies are placed, false if not (ended, or {@code timeout}
     * elapsed).
     */
    public boolean awaitBodies(Duration timeout) throws InterruptedException {
        return host.settled().await(timeout.toMillis(), TimeUnit.MILLISECONDS) && host.bodiesReady();
    }

    /** The line saying this container's bodies are placed ({@link Readiness#container}). */
    public String readiness() {
        return Readiness.container(name, platform, hostedAgents());
    }

    /**
     * Why the mission ended without its coordinator saying so (the coordinator or the platform's main
     * container can no longer be reached: its JVM died); empty while it has not, or if it ended normally.
     */
    public Optional<String> lostPlatform() {
        return Optional.ofNullable(host.lost());
    }

    /**
     * Why this container could not create the bodies its coordinator placed in it (their class
     * cannot be loaded or initialised here, their descriptor is not on this host's agent path), in
     * the words the coordinator reports too; the mission ends then. Empty if it could, or has not been asked.
     */
    public Optional<String> unhosted() {
        return Optional.ofNullable(host.unhosted());
    }

    /**
     * The secret of the mission this container served, once a control message of its coordinator
     * bore it; empty before. A container serving one mission after another ({@code masl container
     * --serve}) joins the next platform only once the secret file holds another secret: until then
     * the platform at its address is the one whose mission just ended.
     */
    public Optional<MissionSecret> missionSecret() {
        return Optional.ofNullable(host.secret());
    }

    /** The agents whose bodies the coordinator placed in this container, in its order. */
    public List<String> hostedAgents() {
        return host.hosted();
    }

    /** Deletes the bodies if the mission has not ended, and closes the container. */
    @Override
    public void close() {
        endingAlready();
        platform.close();
    }

    /**
     * Closes the container as {@link #close()} does, without waiting for JADE's threads to end
     * ({@link JadePlatform#leave()}): this JVM joins the next mission's platform at once.
     */
    public void leave() {
        endingAlready();
        platform.leave();
    }

    /** If JADE deleted the host, the platform's shutdown may be ending this container: closing first waits for that end. */
    private void endingAlready() {
        if (host.takenDown()) {
            platform.endedByItsPlatform();
        }
    }
}
