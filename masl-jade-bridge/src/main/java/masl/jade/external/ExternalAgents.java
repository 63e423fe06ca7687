package masl.jade.external;

import jade.core.AID;
import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.wrapper.AgentController;
import jade.wrapper.StaleProxyException;
import java.lang.reflect.Method;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import java.util.stream.Collectors;
import masl.jade.PrimitiveTable;
import masl.jade.platform.AgentDeletion;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadePlatform;
import masl.jade.stub.StubClasses;
import masl.runtime.AgentImplementation;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.FipaBinding;
import masl.runtime.descriptor.Primitive;

/**
 * The agents of one mission whose types are answered by external FIPA agents ({@code <Fipa>}): for
 * each, an {@link ExternalAgentHost} named after it (its program runs there) and a stub of its
 * implementation class whose own primitives (not {@code Default}'s, which run here) are requests to
 * the FIPA agent ({@link FipaBody}). Before the mission starts each is matched with its FIPA agent:
 * by {@code agent_name}, or by DF {@code service_type}, waiting up to the agents' timeout for one to
 * register; agents of one binding take the providers found in turn (sorted by name). One mission.
 *
 * <p>Public for {@link masl.jade.JadeLauncher}, which makes the stubs and starts the agents of the
 * mission's external agents.
 */
public final class ExternalAgents {

    private final Duration limit;
    private final Duration agentsTimeout;
    private final Consumer<String> problems;
    private final StubClasses stubs = new StubClasses();
    private final Map<Integer, External> externals = new LinkedHashMap<>();
    private final List<AgentController> controllers = new ArrayList<>();

    private record External(String name, FipaBinding binding, ExternalAgentHost host, FipaBody body) {
    }

    /**
     * @param limit    how long a request may go unanswered before the caller perceives {@code timeout}
     * @param problems told one line for each answer whose content cannot be used
     */
    public ExternalAgents(Duration limit, Duration agentsTimeout, Consumer<String> problems) {
        this.limit = limit;
        this.agentsTimeout = agentsTimeout;
        this.problems = problems;
    }

    public static boolean isExternal(AgentType type) {
        return type.fipa().isPresent();
    }

    /** The stand-in of agent {@code proxyId}, of external type {@code type}. */
    public AgentImplementation stub(int proxyId, String name, AgentType type, Class<? extends AgentImplementation> implementation) {
        Set<String> local = rootType(type).primitives().stream().map(Primitive::name).collect(Collectors.toSet());
        PrimitiveTable table = new PrimitiveTable(type, implementation);
        List<Method> forwarded = new ArrayList<>();
        List<Primitive> primitives = table.primitives();
        for (int i = 0; i < primitives.size(); i++) {
            if (!local.contains(primitives.get(i).name())) {
                forwarded.add(table.methods().get(i));
            }
        }
        ExternalAgentHost host = new ExternalAgentHost(name);
        FipaBody body = new FipaBody(name, type.fipa().orElseThrow(), forwarded, host, limit, problems);
        externals.put(proxyId, new External(name, type.fipa().orElseThrow(), host, body));
        return stubs.instantiate(implementation, forwarded, body);
    }

    private static AgentType rootType(AgentType type) {
        AgentType root = type;
        while (root.supertype() != null) {
            root = root.supertype();
        }
        return root;
    }

    public int count() {
        return externals.size();
    }

    public boolean hosts(int proxyId) {
        return externals.containsKey(proxyId);
    }

    /** The JADE agent standing for external agent {@code proxyId}, whose threaded behaviour runs its program. */
    public Agent host(int proxyId) {
        return externals.get(proxyId).host();
    }

    /**
     * Starts the hosts in {@code platform}'s container and finds each agent's FIPA agent.
     *
     * @throws JadeException if a host cannot start, or no FIPA agent offers a service type in time
     */
    public void start(JadePlatform platform) throws InterruptedException, StaleProxyException {
        for (External external : externals.values()) {
            AgentController controller = platform.container().acceptNewAgent(external.name(), external.host());
            controllers.add(controller);
            controller.start();
        }
        for (External external : externals.values()) {
            if (!external.host().awaitStarted(agentsTimeout.toMillis())) {
                throw new JadeException("the JADE agent of " + external.name() + " did not start within "
                        + agentsTimeout);
            }
        }
        Map<String, List<AID>> providers = new HashMap<>();
        Map<String, Integer> taken = new HashMap<>();
        for (External external : externals.values()) {
            String serviceType = external.binding().serviceType();
            if (serviceType == null) {
                String name = external.binding().agentName();
                external.body().peer(new AID(name, name.contains("@") ? AID.ISGUID : AID.ISLOCALNAME));
                continue;
            }
            List<AID> found = providers.computeIfAbsent(serviceType, type -> search(external.host(), type));
            int turn = taken.merge(serviceType, 1, Integer::sum) - 1;
            external.body().peer(found.get(turn % found.size()));
        }
    }

    private List<AID> search(ExternalAgentHost searcher, String serviceType) {
        DFAgentDescription template = new DFAgentDescription();
        ServiceDescription service = new ServiceDescription();
        service.setType(serviceType);
        template.addServices(service);
        try {
            DFAgentDescription[] found = DFService.searchUntilFound(searcher, searcher.getDefaultDF(), template, null,
                    agentsTimeout.toMillis());
            if (found == null || found.length == 0) {
                throw new JadeException("no FIPA agent offers the service type " + serviceType + " (DF) within "
                        + agentsTimeout.toSeconds() + " s");
            }
            return Arrays.stream(found).map(DFAgentDescription::getName)
                    .sorted(Comparator.comparing(AID::getName)).toList();
        } catch (FIPAException e) {
            throw new JadeException("the DF did not answer the search for " + serviceType + ": " + e.getMessage(), e);
        }
    }

    /** Deletes the hosts and waits, bounded, until their threads have ended. */
    public void close() throws InterruptedException {
        // One bound for both waits: deleting, then the threads' ends, normally at once after.
        long deadline = System.nanoTime() + agentsTimeout.toNanos();
        AgentDeletion.oneByOne(controllers, agentsTimeout);
        for (External external : externals.values()) {
            Thread thread = external.host().thread();
            if (thread != null) {
                thread.join(Math.max(1, (deadline - System.nanoTime()) / 1_000_000));
            }
        }
    }
}
