package masl.jade;

import jade.core.Agent;
import jade.wrapper.AgentController;
import jade.wrapper.StaleProxyException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.jade.deployment.Coordination;
import masl.jade.deployment.StandInsOnAPool;
import masl.jade.external.ExternalAgents;
import masl.jade.outside.EventSubscribers;
import masl.jade.outside.OutsideCalls;
import masl.jade.placement.ContainerTraffic;
import masl.jade.placement.DeployedSource;
import masl.jade.placement.Distribution;
import masl.jade.placement.MaslContainer;
import masl.jade.placement.ProgramTranslator;
import masl.jade.platform.AgentDeletion;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.trust.MissionSecret;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram.AgentSpec;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentType;
import masl.runtime.trace.Trace;

/**
 * Runs a translated MASL program inside JADE ({@code masl run --platform jade}): one JADE agent per
 * MASL agent, named after it, registered with the DF, answering FIPA requests, each MASL program
 * running in a threaded behaviour of its JADE agent ({@link MaslJadeAgent},
 * {@link ThreadedBehaviourScheduler}; a deployed agent's stand-in runs on a pool instead,
 * {@link StandInsOnAPool}). The mission starts once every JADE agent exists and is
 * registered; afterwards the JADE agents are deleted (and deregistered). The outcome is the one the
 * runtime gives in-process: status, journal, report. With {@link #place}, the bodies of some agents
 * live in other containers ({@link MaslContainer}) while every program still runs here, through the
 * {@code masl-coordinator} agent ({@link Distribution}).
 *
 * <pre>{@code
 * MissionOutcome outcome = JadeLauncher.of(program)
 *         .types(spec -> loader.loadByClassName(spec.typeClassName()))
 *         .journal(System.out)
 *         .run(JadeOptions.mainContainer(), Duration.ofMinutes(5));
 * }</pre>
 *
 * <p>One launcher may run its program several times, one mission at a time; not thread-safe.
 */
public final class JadeLauncher {

    /** How long the JADE agents may take to start and register, and to end after the mission. */
    private static final Duration AGENTS_TIMEOUT = Duration.ofSeconds(30);

    private final MissionProgram program;
    private Function<AgentSpec, AgentType> types;
    private MissionProgram.ImplementationFactory implementations = JadeLauncher::newImplementation;
    private Appendable journal;
    private Trace trace = Trace.NONE;
    private Consumer<Mission> whenReady = mission -> { };
    private Map<String, String> placement = Map.of();
    private Map<String, String> deployment = Map.of();
    private DeployedSource deployedSource;
    private ContainerTraffic traffic;
    private MissionSecret secret;
    private Duration containersWithin = AGENTS_TIMEOUT;
    private Duration callTimeout;
    private Consumer<String> problems = line -> System.err.println("masl: " + line);

    private JadeLauncher(MissionProgram program) {
        this.program = Objects.requireNonNull(program, "program");
    }

    public static JadeLauncher of(MissionProgram program) {
        return new JadeLauncher(program);
    }

    /** The agent type of each agent (its descriptor): which primitives it offers. Required. */
    public JadeLauncher types(Function<AgentSpec, AgentType> agentTypes) {
        this.types = Objects.requireNonNull(agentTypes, "agentTypes");
        return this;
    }

    /** Makes each agent's implementation; by default the no-argument constructor of its type's class. */
    public JadeLauncher implementations(MissionProgram.ImplementationFactory factory) {
        this.implementations = Objects.requireNonNull(factory, "factory");
        return this;
    }

    /** Where the journal is written as it grows (besides the outcome's journal). */
    public JadeLauncher journal(Appendable sink) {
        this.journal = sink;
        return this;
    }

    public JadeLauncher trace(Trace missionTrace) {
        this.trace = Objects.requireNonNull(missionTrace, "missionTrace");
        return this;
    }

    /**
     * Places agents in other containers, by name: {@code {"w1": "c2"}} runs the body of {@code w1}
     * (its implementation, whose primitives run there) in container {@code c2}, which joined the
     * platform as a {@link MaslContainer}; its program runs here, in the coordinator's JVM, with
     * every other agent's. Agents not named stay in this container. Empty by default: the whole
     * mission in one container.
     */
    public JadeLauncher place(Map<String, String> containerOfAgent) {
        this.placement = Map.copyOf(containerOfAgent);
        return this;
    }

    /**
     * Deploys agents' programs to other containers, by name: {@code {"a": "c2"}} runs agent {@code a}'s
     * program and implementation in container {@code c2} ({@link MaslContainer} with a
     * {@link ProgramTranslator}), which translates {@code source} itself and refuses it if its
     * translation's key is not {@code source}'s. The mission stays here: blocks, barriers, shared
     * variables, events, permeability, the watchdog, the journal and the trace; the deployed program's
     * requests for them are signed messages. An agent is deployed or placed, not both.
     */
    public JadeLauncher deploy(Map<String, String> containerOfAgent, DeployedSource source) {
        this.deployment = Map.copyOf(containerOfAgent);
        this.deployedSource = containerOfAgent.isEmpty() ? null : Objects.requireNonNull(source, "source");
        return this;
    }

    /**
     * Counts into {@code counts} the messages between the coordinator and each container: deployed
     * agents' coordination messages, and placed bodies' requests and answers.
     */
    public JadeLauncher traffic(ContainerTraffic counts) {
        this.traffic = Objects.requireNonNull(counts, "counts");
        return this;
    }

    /**
     * Bounds every primitive call of the mission as {@link Mission.Builder#callTimeout} does, and every
     * call a FIPA agent from outside the mission makes. Without it, the mission's calls are not bounded
     * and outsiders' calls are bounded by {@link OutsideCalls#DEFAULT_LIMIT} (10 s): an agent serves them
     * on its behalf, and its program waits meanwhile.
     */
    public JadeLauncher callTimeout(Duration timeout) {
        if (timeout.isNegative() || timeout.isZero()) {
            throw new IllegalArgumentException("a call timeout must be positive: " + timeout);
        }
        this.callTimeout = timeout;
        return this;
    }

    /**
     * Told one line for each answer of an external FIPA agent ({@code <Fipa>} types) whose content
     * cannot be used; by default standard error, after {@code masl: }.
     */
    public JadeLauncher problems(Consumer<String> sink) {
        this.problems = Objects.requireNonNull(sink, "sink");
        return this;
    }

    /**
     * The secret the containers of {@link #place} know too (out of band: {@link MissionSecret#writeTo}):
     * the coordinator signs its control messages with it, and they obey only those. Required with a
     * placement.
     */
    public JadeLauncher secret(MissionSecret missionSecret) {
        this.secret = Objects.requireNonNull(missionSecret, "missionSecret");
        return this;
    }

    /**
     * How long the mission waits for each container of {@link #place} to join the platform and prove
     * it holds the mission's secret before it fails without starting; 30 s by default.
     */
    public JadeLauncher containersWithin(Duration limit) {
        if (limit.isNegative() || limit.isZero()) {
            throw new IllegalArgumentException("the wait for containers must be positive: " + limit);
        }
        this.containersWithin = limit;
        return this;
    }

    /**
     * Called on the launching thread once every JADE agent of a mission exists and is registered with
     * the DF, with the mission about to run: from then on FIPA agents can find and invoke them, and
     * the caller may {@link Mission#stop()} it (on Ctrl-C, say).
     */
    public JadeLauncher whenReady(Consumer<Mission> action) {
        this.whenReady = Objects.requireNonNull(action, "action");
        return this;
    }

    /**
     * Starts a container as {@code options} say, runs the mission in it, and closes the container
     * (a main container: the whole platform), leaving no JADE thread behind.
     *
     * @throws JadeException if the container cannot start, or the agents cannot be created
     * @throws InterruptedException if the calling thread is interrupted meanwhile
     */
    public MissionOutcome run(JadeOptions options, Duration timeout) throws InterruptedException {
        try (JadePlatform platform = JadePlatform.start(options)) {
            return run(platform, timeout);
        }
    }

    /**
     * Runs the mission in an open container; its agents are gone from the platform on return.
     *
     * @throws JadeException if an agent's name is taken on the platform, an implementation lacks a
     *                       primitive of its type, or the agents do not start or register
     * @throws InterruptedException if the calling thread is interrupted meanwhile
     */
    public MissionOutcome run(JadePlatform platform, Duration timeout) throws InterruptedException {
        if (types == null) {
            throw new IllegalStateException("agent types not given: call types(…) first");
        }
        List<AgentSpec> specs = program.agents();
        List<String> names = specs.stream().map(AgentSpec::name).toList();
        for (String placed : placement.keySet()) {
            if (!names.contains(placed)) {
                throw new IllegalArgumentException("cannot place " + placed + ": the program declares no agent of"
                        + " that name (it declares " + String.join(", ", names) + ")");
            }
        }
        for (String deployed : deployment.keySet()) {
            if (!names.contains(deployed)) {
                throw new IllegalArgumentException("cannot deploy " + deployed + ": the program declares no agent of"
                        + " that name (it declares " + String.join(", ", names) + ")");
            }
            if (placement.containsKey(deployed)) {
                throw new IllegalArgumentException("cannot deploy " + deployed + ": it is placed (deploy or place it)");
            }
        }
        if ((!placement.isEmpty() || !deployment.isEmpty()) && secret == null) {
            throw new IllegalStateException("a mission placing bodies or deploying programs in other containers needs"
                    + " their secret: call secret(…) first");
        }
        Distribution distribution = placement.isEmpty() && deployment.isEmpty() ? null
                : new Distribution(platform, placement, secret, AGENTS_TIMEOUT, containersWithin, problems);
        if (distribution != null && traffic != null) {
            distribution.countInto(traffic);
        }
        List<AgentController> controllers = new ArrayList<>();
        List<MaslJadeAgent> locals = new ArrayList<>();
        Duration limit = callTimeout == null ? OutsideCalls.DEFAULT_LIMIT : callTimeout;
        OutsideCalls outside = new OutsideCalls(limit);
        ExternalAgents externals = new ExternalAgents(limit, AGENTS_TIMEOUT, problems);
        try {
            return run(platform, timeout, specs, names, distribution, outside, externals, controllers, locals);
        } catch (StaleProxyException e) {
            throw new JadeException("the JADE container ended before the mission", e);
        } finally {
            try {
                if (distribution != null) {
                    distribution.end();
                }
            } finally {
                outside.close();
                delete(controllers, locals);
                externals.close();
            }
        }
    }

    private MissionOutcome run(JadePlatform platform, Duration timeout, List<AgentSpec> specs, List<String> names,
            Distribution distribution, OutsideCalls outside, ExternalAgents externals,
            List<AgentController> controllers, List<MaslJadeAgent> locals)
            throws InterruptedException, StaleProxyException {
        List<AgentImplementation> created = new ArrayList<>();
        ThreadedBehaviourScheduler scheduler = new ThreadedBehaviourScheduler();
        AtomicReference<Mission> built = new AtomicReference<>();
        Coordination coordination = deployment.isEmpty() ? null : new Coordination(
                Coordination.mainOf(program, implementations), distribution::wireTo,
                text -> built.get().journal().append(text));
        // FIPA agents may invoke primitives at any time: a busy-wait may end on a request.
        EventSubscribers subscribers = new EventSubscribers(names);
        Mission.Builder builder = Mission.builder()
                .scheduler(coordination == null ? scheduler : new StandInsOnAPool(scheduler, coordination))
                .openToOutsideInvocations()
                .trace(subscribers.forwarding(distribution == null ? trace : distribution.sendingEvents(trace, names)));
        if (journal != null) {
            builder.journal(journal);
        }
        if (callTimeout != null) {
            builder.callTimeout(callTimeout);
        }
        if (coordination != null) {
            // A deployed agent's program runs in its container; here, a stand-in whose steps are its.
            builder.programs((name, own) -> deployment.containsKey(name)
                    ? coordination.standIn(names.indexOf(name), own) : own);
        }
        program.configure(builder, spec -> {
            AgentImplementation implementation = implementations.create(spec);
            String container = distribution == null ? null : distribution.containerOf(spec.name());
            AgentType type = types.apply(spec);
            if (ExternalAgents.isExternal(type)) {
                if (container != null || deployment.containsKey(spec.name())) {
                    throw new JadeException("cannot place " + spec.name() + ": an external FIPA agent answers its"
                            + " primitives (its type " + type.shortName() + " has <Fipa>)");
                }
                // Its primitives are requests to an external FIPA agent; its program runs here.
                implementation = externals.stub(created.size(), spec.name(), type, implementation.getClass());
            } else if (container != null) {
                // Its body lives in that container; here, a stub whose primitives are requests to it.
                implementation = distribution.stub(created.size(), spec.name(), container, types.apply(spec),
                        implementation.getClass());
            }
            if (coordination != null) {
                // A deployed agent's primitives run in its container; deployed agents name others' members.
                implementation = coordination.implementationOf(created.size(), type, implementation,
                        deployment.containsKey(spec.name()));
            }
            created.add(implementation);
            return implementation;
        });
        Mission mission = builder.build();
        built.set(mission);
        subscribers.of(mission);
        if (created.size() != specs.size()) {
            throw new IllegalStateException(program.getClass().getName() + " declares " + specs.size()
                    + " agents but made " + created.size() + " through the implementation factory");
        }
        List<PrimitiveTable> tables = new ArrayList<>();
        for (int id = 0; id < specs.size(); id++) {
            tables.add(new PrimitiveTable(types.apply(specs.get(id)), created.get(id).getClass()));
        }
        List<Agent> hosts = new ArrayList<>();
        CountDownLatch ready = new CountDownLatch(specs.size() - placement.size() - externals.count());
        for (int id = 0; id < specs.size(); id++) {
            if (placement.containsKey(names.get(id))) {
                // Runs the program; the body is elsewhere, and its JADE agent there.
                hosts.add(distribution.coordinator());
                continue;
            }
            if (externals.hosts(id)) {
                hosts.add(externals.host(id));
                continue;
            }
            MaslJadeAgent host = new MaslJadeAgent(id, created.get(id), tables.get(id), mission, outside, subscribers,
                    ready);
            controllers.add(create(platform, names.get(id), host));
            locals.add(host);
            hosts.add(host);
        }
        for (AgentController controller : controllers) {
            controller.start();
        }
        // Agents that message others right after start() can stall JADE (platform-notes.md):
        // the mission starts only once every agent exists and is registered.
        if (!ready.await(AGENTS_TIMEOUT.toMillis(), TimeUnit.MILLISECONDS)) {
            throw new JadeException("the JADE agents of the mission did not start within " + AGENTS_TIMEOUT);
        }
        for (MaslJadeAgent host : locals) {
            if (host.registrationFailure() != null) {
                throw new JadeException("the DF refused to register " + host.getLocalName() + ": "
                        + host.registrationFailure().getMessage(), host.registrationFailure());
            }
        }
        externals.start(platform);
        if (coordination != null) {
            coordination.agents(mission, created);
            distribution.deploy(deployment, deployedSource, coordination, names);
        }
        if (distribution != null) {
            distribution.place(mission, names, tables, created, outside);
        }
        scheduler.attach(hosts);
        whenReady.accept(mission);
        return mission.run(timeout);
    }

    private static AgentController create(JadePlatform platform, String name, MaslJadeAgent host) {
        try {
            return platform.container().acceptNewAgent(name, host);
        } catch (StaleProxyException e) {
            throw new JadeException("cannot create JADE agent " + name + " (is the name taken on the platform?)", e);
        }
    }

    /** Deletes the mission's JADE agents and waits, bounded, until their threads have ended. */
    private static void delete(List<AgentController> controllers, List<MaslJadeAgent> hosts)
            throws InterruptedException {
        // One bound for both waits: deleting, then the threads' ends, normally at once after.
        long deadline = System.nanoTime() + AGENTS_TIMEOUT.toNanos();
        AgentDeletion.oneByOne(controllers, AGENTS_TIMEOUT);
        for (MaslJadeAgent host : hosts) {
            Thread thread = host.thread();
            if (thread != null) {
                thread.join(Math.max(1, (deadline - System.nanoTime()) / 1_000_000));
            }
        }
    }

    private static AgentImplementation newImplementation(AgentSpec spec) throws ReflectiveOperationException {
        ClassLoader loader = Thread.currentThread().getContextClassLoader();
        Class<?> type = Class.forName(spec.typeClassName(), true,
                loader != null ? loader : JadeLauncher.class.getClassLoader());
        return type.asSubclass(AgentImplementation.class).getConstructor().newInstance();
    }
}
