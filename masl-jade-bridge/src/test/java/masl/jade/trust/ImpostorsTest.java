package masl.jade.trust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.DFService;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import masl.jade.Detonator;
import masl.jade.DfEntries;
import masl.jade.JadeLauncher;
import masl.jade.Probe;
import masl.jade.ServiceAgent;
import masl.jade.TestPrograms;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.Conversations;
import masl.jade.placement.MaslContainer;
import masl.jade.platform.AmsActions;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.testing.jade.JadePlatformExtension;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Plain JADE agents without the mission's secret pose as parties of a mission spanning containers:
 * as its container (a DF entry of the container's name, registered before the real container joins,
 * answering the placement), as a body (after killing the real one through the AMS and taking its
 * name, answering the coordinator's requests with a result and journal lines, or a failure), and as
 * a body relaying a request. Each forged message is refused and said in one line by the coordinator,
 * and changes nothing: the real container is placed, no forged result or journal line is taken.
 * About 3 s each (containers of this JVM, each living at least 3 s; each closed once its mission ended, so
 * that the coordinator does not wait for it to leave).
 */
@Timeout(180)
@Tag("slow")
class ImpostorsTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(60);
    private static final MissionSecret SECRET = MissionSecret.generate();

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void aForgedPlacementInformDoesNotWinOverTheRealContainerJoiningLater() throws Exception {
        impostorContainerLosesToTheRealOne("c5", ACLMessage.INFORM, "{\"result\":null}");
    }

    @Test
    void aForgedPlacementFailureDoesNotWinOverTheRealContainerJoiningLater() throws Exception {
        impostorContainerLosesToTheRealOne("c6", ACLMessage.FAILURE,
                "{\"exception\":\"java.lang.IllegalStateException\",\"message\":\"forged\"}");
    }

    private void impostorContainerLosesToTheRealOne(String name, int performative, String content) throws Exception {
        Answering impostor = new Answering(performative, content);
        JADE.platform().container().acceptNewAgent("impostor-" + name, impostor).start();
        DFService.register(impostor, DfEntries.service(impostor.getAID(), DfEntries.CONTAINER_SERVICE, name));
        BlockingQueue<String> problems = new LinkedBlockingQueue<>();
        LetThrough let = new LetThrough();
        let.go.complete(null);
        CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(JadeLauncher.of(let.program())
                .types(TestPrograms::type).place(Map.of("b", name)).secret(SECRET).problems(problems::add),
                JADE.platform(), TIMEOUT);
        ACLMessage asked = impostor.requests.poll(60, TimeUnit.SECONDS);
        if (asked == null) {
            mission.get(1, TimeUnit.SECONDS);
        }
        assertEquals(Conversations.PLACE, asked.getConversationId());
        try (MaslContainer container = ForgedMessagesTest.container(JADE.platform(), name, SECRET)) {
            String refused = problems.poll(20, TimeUnit.SECONDS);
            assertTrue(refused != null && refused.startsWith("refused " + ACLMessage.getPerformative(performative)
                    + " masl-place from " + impostor.getName()) && refused.endsWith(": not signed with the mission's"
                    + " secret"), refused);
            assertTrue(container.awaitMissionEnd(Duration.ofSeconds(60)), "the coordinator's own end");
            container.close();
            MissionOutcome outcome = mission.get(60, TimeUnit.SECONDS);
            outcome.requireCompleted();
            assertEquals(List.of(5), let.results, "the real body's result");
            assertEquals(List.of("b"), container.hostedAgents());
            assertEquals("container " + name + " is claimed by " + impostor.getName() + ", which did not prove it"
                    + " holds the mission's secret: ignored", problems.poll(20, TimeUnit.SECONDS));
        } finally {
            impostor.doDelete();
        }
    }

    @Test
    void aForgedBodyResultWithJournalLinesIsRefused() throws Exception {
        impostorBodyIsRefused("c7", ACLMessage.INFORM, "{\"result\":4242,\"journal\":\"FORGED by evil\\n\"}");
    }

    @Test
    void aForgedBodyFailureIsRefused() throws Exception {
        impostorBodyIsRefused("c8", ACLMessage.FAILURE,
                "{\"exception\":\"" + Detonator.class.getName() + "\",\"message\":\"boom\",\"journal\":\"FORGED\\n\"}");
    }

    /**
     * The real body {@code b} is placed, then killed through the AMS by an agent that takes its name
     * and answers the coordinator's next request: the answer is refused, the call stays unanswered
     * (the test then stops the mission), and nothing of the answer reaches the mission.
     */
    private void impostorBodyIsRefused(String name, int performative, String content) throws Exception {
        BlockingQueue<String> problems = new LinkedBlockingQueue<>();
        LetThrough let = new LetThrough();
        CompletableFuture<Mission> running = new CompletableFuture<>();
        try (MaslContainer container = ForgedMessagesTest.container(JADE.platform(), name, SECRET)) {
            CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(JadeLauncher.of(let.program())
                    .types(TestPrograms::type).place(Map.of("b", name)).secret(SECRET).problems(problems::add)
                    .whenReady(running::complete), JADE.platform(), TIMEOUT);
            assertTrue(container.awaitBodies(TIMEOUT), "the real body placed");
            Answering impostor = new Answering(performative, content);
            JADE.platform().container().acceptNewAgent("killer-" + name, impostor).start();
            AmsActions.kill(impostor, new AID("b", AID.ISLOCALNAME));
            Answering body = new Answering(performative, content);
            JADE.platform().container().acceptNewAgent("b", body).start();
            let.go.complete(null);
            assertEquals(Conversations.BODY, body.requests.poll(60, TimeUnit.SECONDS).getConversationId());
            String refused = problems.poll(20, TimeUnit.SECONDS);
            assertTrue(refused != null && refused.startsWith("refused " + ACLMessage.getPerformative(performative)
                    + " masl-body from " + body.getName()) && refused.endsWith(": not signed with the mission's"
                    + " secret"), refused);
            running.get(60, TimeUnit.SECONDS).stop("the test");
            assertTrue(container.awaitMissionEnd(TIMEOUT), "the coordinator's end of the stopped mission");
            container.close();
            MissionOutcome outcome = mission.get(60, TimeUnit.SECONDS);
            assertEquals(MissionOutcome.Status.STOPPED, outcome.status(), outcome.toString());
            assertFalse(let.results.contains(4242), let.results.toString());
            assertFalse(outcome.journal().contains("FORGED"), outcome.journal());
            assertNull(System.getProperty(Detonator.MARK), "the class a forged FAILURE named was initialised");
            body.doDelete();
            impostor.doDelete();
        }
    }

    /**
     * A relay ({@value Conversations#RELAY}) naming body {@code b} as its sender but not signed is
     * refused: the coordinator does not run the request it carries.
     */
    @Test
    void aForgedRelayIsRefused() throws Exception {
        ServiceAgent.Gate gate = new ServiceAgent.Gate();
        ServiceAgent.gate = gate;
        BlockingQueue<String> problems = new LinkedBlockingQueue<>();
        List<Integer> results = new CopyOnWriteArrayList<>();
        Probe forger = new Probe();
        JADE.platform().container().acceptNewAgent("relay-forger", forger).start();
        try (MaslContainer container = ForgedMessagesTest.container(JADE.platform(), "c9", SECRET)) {
            CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(JadeLauncher.of(
                    ForgedMessagesTest.callsGated(results)).types(TestPrograms::type).place(Map.of("b", "c9"))
                    .secret(SECRET).problems(problems::add), JADE.platform(), TIMEOUT);
            gate.entered().get(60, TimeUnit.SECONDS);
            ACLMessage relay = AclInvocations.request(new AID(Conversations.COORDINATOR, AID.ISLOCALNAME), "log",
                    List.of("RELAYED"), null);
            relay.setConversationId(Conversations.RELAY);
            relay.setReplyWith("forged-relay");
            relay.setSender(new AID("b", AID.ISLOCALNAME));
            forger.sendMessage(relay);
            String refused = problems.poll(20, TimeUnit.SECONDS);
            assertTrue(refused != null && refused.startsWith("refused REQUEST masl-relay from b@")
                    && refused.endsWith(": not signed with the mission's secret"), refused);
            gate.result().complete(7);
            assertTrue(container.awaitMissionEnd(Duration.ofSeconds(30)), "the coordinator's own end");
            container.close();
            MissionOutcome outcome = mission.get(60, TimeUnit.SECONDS);
            outcome.requireCompleted();
            assertEquals(List.of(7), results);
            assertEquals("", outcome.journal());
        } finally {
            forger.doDelete();
        }
    }

    /** A plain JADE agent answering every request it gets with the same forged answer, keeping the requests. */
    static final class Answering extends Agent {
        private static final long serialVersionUID = 1L;

        final transient BlockingQueue<ACLMessage> requests = new LinkedBlockingQueue<>();
        private final int performative;
        private final String content;

        Answering(int performative, String content) {
            this.performative = performative;
            this.content = content;
        }

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                private static final long serialVersionUID = 1L;

                @Override
                public void action() {
                    ACLMessage request = myAgent.receive(MessageTemplate.and(
                            MessageTemplate.MatchPerformative(ACLMessage.REQUEST),
                            MessageTemplate.not(MessageTemplate.MatchSender(getAMS()))));
                    if (request == null) {
                        block();
                        return;
                    }
                    ACLMessage answer = request.createReply();
                    answer.setPerformative(performative);
                    answer.setContent(content);
                    myAgent.send(answer);
                    requests.add(request);
                }
            });
        }
    }

    /** Agent {@code b} calls {@code add(2, 3)} on its body once the test lets it ({@link #go}). */
    static final class LetThrough {
        final CompletableFuture<Void> go = new CompletableFuture<>();
        final List<Integer> results = new CopyOnWriteArrayList<>();

        MissionProgram program() {
            return ForgedMessagesTest.callsOnce(results, "add", body -> () -> {
                go.join();
                return body.add(2, 3);
            });
        }
    }
}
