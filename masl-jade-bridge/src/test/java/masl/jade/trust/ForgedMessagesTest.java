package masl.jade.trust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.jade.Detonator;
import masl.jade.JadeLauncher;
import masl.jade.Probe;
import masl.jade.ServiceAgent;
import masl.jade.TestPrograms;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.Conversations;
import masl.jade.placement.MaslContainer;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.runtime.AgentContext;
import masl.runtime.EntryDefinition;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.Mode;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import masl.testing.jade.JadePlatformExtension;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Agents of the platform that are not part of a mission spanning containers forge the messages its
 * coordinator and containers exchange, while agent {@code b}'s program waits for its body (in
 * container {@code c2}, of this JVM) to answer a call the test holds open. The mission must go on as
 * if they had sent nothing.
 */
@Timeout(180)
public class ForgedMessagesTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(60);
    /**
     * How long a mission waits for a container that proves itself: the container's refusal, an exchange
     * within this JVM, comes back long before.
     */
    private static final Duration CONTAINERS_WITHIN = Duration.ofSeconds(5);
    /** How many of the coordinator's former, sequential conversation ids a forger tries. */
    private static final int GUESSES = 20;
    private static final MissionSecret SECRET = MissionSecret.generate();

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    private static Probe forger;

    @BeforeAll
    static void startForger() throws Exception {
        forger = new Probe();
        JADE.platform().container().acceptNewAgent("forger", forger).start();
    }

    /**
     * The forger answers the coordinator's guessable conversations with a result, a journal and a
     * failure naming a class with a static initialiser: each is refused, the call gets the body's
     * own result, the journal stays the mission's, and the class is never initialised.
     */
    @Test
    void answersForgedByAnotherAgentAreRefusedAndNoClassTheyNameIsLoaded() throws Exception {
        ServiceAgent.Gate gate = new ServiceAgent.Gate();
        ServiceAgent.gate = gate;
        List<Integer> results = new CopyOnWriteArrayList<>();
        try (MaslContainer container = container("c2")) {
            CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(
                    JadeLauncher.of(callsGated(results)).types(TestPrograms::type).place(Map.of("b", "c2"))
                            .secret(SECRET),
                    JADE.platform(), TIMEOUT);
            gate.entered().get(60, TimeUnit.SECONDS);
            AID coordinator = new AID(Conversations.COORDINATOR, AID.ISLOCALNAME);
            for (int id = 1; id <= GUESSES; id++) {
                forger.sendMessage(answer(coordinator, ACLMessage.INFORM, "masl-coordinator-" + id,
                        "{\"result\":666,\"journal\":\"SPOOFED\\n\"}"));
                forger.sendMessage(answer(coordinator, ACLMessage.FAILURE, "masl-coordinator-" + id,
                        "{\"exception\":\"" + Detonator.class.getName() + "\",\"message\":\"boom\"}"));
            }
            for (int answered = 0; answered < 2 * GUESSES; answered++) {
                ACLMessage reply = forger.next();
                assertEquals(ACLMessage.NOT_UNDERSTOOD, reply.getPerformative(), reply.toString());
            }
            gate.result().complete(7);
            assertTrue(container.awaitMissionEnd(Duration.ofSeconds(30)), "the coordinator's own end");
            container.close();
            MissionOutcome outcome = mission.get(60, TimeUnit.SECONDS);
            outcome.requireCompleted();
            assertEquals(List.of(7), results, "the body's own result");
            assertEquals("", outcome.journal());
            assertNull(System.getProperty(Detonator.MARK), "the class a forged FAILURE named was initialised");
        }
    }

    /**
     * The forger ends the container, places a body of its own over {@code b}, and sends it an event,
     * with its own name and with the coordinator's: each is refused, said in one line, and changes
     * nothing; the real coordinator's calls, event-free mission and end go through.
     */
    @Test
    void controlMessagesForgedByAnotherAgentAreRefusedAndChangeNothing() throws Exception {
        ServiceAgent.Gate gate = new ServiceAgent.Gate();
        ServiceAgent.gate = gate;
        List<Integer> results = new CopyOnWriteArrayList<>();
        BlockingQueue<String> refusals = new LinkedBlockingQueue<>();
        List<String> events = new CopyOnWriteArrayList<>();
        try (MaslContainer container = container("c3", SECRET, refusals, events)) {
            CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(JadeLauncher.of(callsGated(results))
                    .types(TestPrograms::type).place(Map.of("b", "c3")).secret(SECRET), JADE.platform(), TIMEOUT);
            gate.entered().get(60, TimeUnit.SECONDS);
            AID host = new AID(Conversations.containerAgent("c3"), AID.ISLOCALNAME);
            ACLMessage end = control(host, ACLMessage.REQUEST, Conversations.END, "{}");
            forger.sendMessage(end);
            assertEquals(ACLMessage.REFUSE, forger.next().getPerformative(), "a forged masl-end");
            forger.sendMessage(control(host, ACLMessage.REQUEST, Conversations.PLACE,
                    "{\"agents\":[{\"name\":\"b\",\"proxyId\":0,\"class\":\"" + ServiceAgent.class.getName()
                            + "\"}]}"));
            assertEquals(ACLMessage.REFUSE, forger.next().getPerformative(), "a forged masl-place");
            forger.sendMessage(control(host, ACLMessage.INFORM, Conversations.EVENT, "{\"event\":\"go\"}"));
            assertEquals(ACLMessage.NOT_UNDERSTOOD, forger.next().getPerformative(), "a forged masl-event");
            ACLMessage endAsTheCoordinator = control(host, ACLMessage.REQUEST, Conversations.END, "{}");
            endAsTheCoordinator.setSender(new AID(Conversations.COORDINATOR, AID.ISLOCALNAME));
            forger.sendMessage(endAsTheCoordinator);
            assertEquals("refused masl-end from " + forger.getName() + ": only masl-coordinator controls a MASL"
                    + " container", refusals.poll(20, TimeUnit.SECONDS));
            assertEquals("refused masl-place from " + forger.getName() + ": only masl-coordinator controls a MASL"
                    + " container", refusals.poll(20, TimeUnit.SECONDS));
            assertEquals("refused masl-event from " + forger.getName() + ": only masl-coordinator controls a MASL"
                    + " container", refusals.poll(20, TimeUnit.SECONDS));
            String unsigned = refusals.poll(20, TimeUnit.SECONDS);
            assertTrue(unsigned != null && unsigned.startsWith("refused masl-end from masl-coordinator@")
                    && unsigned.endsWith(": not signed with the mission's secret"), unsigned);
            gate.result().complete(7);
            assertTrue(container.awaitMissionEnd(Duration.ofSeconds(30)), "the coordinator's own end");
            container.close();
            MissionOutcome outcome = mission.get(60, TimeUnit.SECONDS);
            outcome.requireCompleted();
            assertEquals(List.of(7), results, "the body's result: it was still there");
            assertEquals(Optional.empty(), container.lostPlatform());
            assertEquals(List.of("b"), container.hostedAgents());
            assertEquals(List.of(), events);
            assertNull(refusals.poll(), "nothing else refused");
        }
    }

    /**
     * A container given another secret than its coordinator's obeys not even the coordinator, and its
     * refusal, which it cannot sign, is no proof that it is the container: the mission does not start
     * (after waiting {@link #CONTAINERS_WITHIN} for a container that can prove it), each side saying why.
     */
    @Test
    void aContainerWithoutTheMissionsSecretHostsNothing() throws Exception {
        BlockingQueue<String> refusals = new LinkedBlockingQueue<>();
        List<String> problems = new CopyOnWriteArrayList<>();
        try (MaslContainer container = container("c4", MissionSecret.generate(), refusals, new CopyOnWriteArrayList<>())) {
            JadeException refused = assertThrows(JadeException.class, () -> JadeLauncher.of(callsGated(new ArrayList<>()))
                    .types(TestPrograms::type).place(Map.of("b", "c4")).secret(SECRET).problems(problems::add)
                    .containersWithin(CONTAINERS_WITHIN).run(JADE.platform(), TIMEOUT));
            assertTrue(refused.getMessage().startsWith("no agent claiming to be container c4 proved it holds the"
                    + " mission's secret within "), refused.getMessage());
            assertEquals(List.of(), container.hostedAgents());
            String line = refusals.poll(20, TimeUnit.SECONDS);
            assertTrue(line != null && line.startsWith("refused masl-place from masl-coordinator@"), line);
            assertTrue(problems.get(0).startsWith("refused REFUSE masl-place from masl-container-c4@")
                    && problems.get(0).endsWith(": not signed with the mission's secret"), problems.toString());
        }
    }

    private static MaslContainer container(String name) {
        return container(name, SECRET, refusal -> { }, new CopyOnWriteArrayList<>());
    }

    /** Container {@code name} of {@code platform}, in this JVM, knowing {@code secret}. */
    public static MaslContainer container(JadePlatform platform, String name, MissionSecret secret) {
        return MaslContainer.start(JadeOptions.join(platform.host(), platform.port()), name,
                className -> TestPrograms.type(new MissionProgram.AgentSpec("", className)),
                ForgedMessagesTest.class.getClassLoader(), event -> { }, MissionSecret.Source.of(secret), refusal -> { });
    }

    private static MaslContainer container(String name, MissionSecret secret, Collection<String> refusals,
            List<String> events) {
        return container(name, secret, (Consumer<String>) refusals::add, events);
    }

    private static MaslContainer container(String name, MissionSecret secret, Consumer<String> refusals,
            List<String> events) {
        return MaslContainer.start(JadeOptions.join(JADE.platform().host(), JADE.platform().port()), name,
                className -> TestPrograms.type(new MissionProgram.AgentSpec("", className)),
                ForgedMessagesTest.class.getClassLoader(), event -> events.add(event.getContent()),
                MissionSecret.Source.of(secret), refusals);
    }

    private static ACLMessage control(AID receiver, int performative, String conversation, String content) {
        ACLMessage message = new ACLMessage(performative);
        message.addReceiver(receiver);
        message.setLanguage(AclInvocations.LANGUAGE);
        message.setOntology(AclInvocations.ONTOLOGY);
        message.setConversationId(conversation);
        message.setReplyWith("forged-" + conversation);
        message.setContent(content);
        return message;
    }

    public static MissionProgram callsGated(List<Integer> results) {
        return callsOnce(results, "gated", body -> body::gated);
    }

    /** Agent {@code b} calling {@code primitive} once ({@link CallsOnce}). */
    static MissionProgram callsOnce(List<Integer> results, String primitive,
            Function<ServiceAgent, Callable<Integer>> call) {
        return TestPrograms.of(CallsOnce.MAIN, List.of(new MissionProgram.AgentSpec("b", ServiceAgent.class.getName())),
                self -> new CallsOnce(self, results, primitive, call));
    }

    private static ACLMessage answer(AID receiver, int performative, String inReplyTo, String content) {
        ACLMessage answer = new ACLMessage(performative);
        answer.addReceiver(receiver);
        answer.setLanguage(AclInvocations.LANGUAGE);
        answer.setOntology(AclInvocations.ONTOLOGY);
        answer.setConversationId(Conversations.BODY);
        answer.setInReplyTo(inReplyTo);
        answer.setContent(content);
        return answer;
    }

    /** In a main block, calls one primitive of its body once ({@code call}), keeping the result. */
    public static final class CallsOnce extends CompactProgram {
        public static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);

        private final List<Integer> results;
        private final String primitive;
        private final Function<ServiceAgent, Callable<Integer>> call;

        public CallsOnce(TestAgent self, List<Integer> results, String primitive, Function<ServiceAgent, Callable<Integer>> call) {
            super(self);
            this.results = results;
            this.primitive = primitive;
            this.call = call;
        }

        @Override
        protected void resume(AgentContext ctx) {
            Callable<Integer> body = call.apply((ServiceAgent) self);
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 3)) return;
                        continue;
                    case 1:
                        results.add(ctx.invokeSelf(primitive, -1, body));
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2:
                        if (!leave(ctx, MAIN, 3)) return;
                        continue;
                    case 3:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }
}
