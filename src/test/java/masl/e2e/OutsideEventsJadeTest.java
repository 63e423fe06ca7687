package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import jade.core.AID;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.lang.acl.ACLMessage;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import masl.jade.platform.JadePlatform;
import masl.jade.platform.Readiness;
import masl.testing.jade.JadePlatformExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A plain JADE agent and a mission's shared events (outsiders/events.masl): it subscribes to them
 * with a {@code SUBSCRIBE} to agent a ({@code AGREE}) and receives each as an {@code INFORM}
 * ({@code masl-event}); it raises {@code go} with an {@code INFORM masl-event}, which both agents
 * react to; an event no block declares is {@code NOT_UNDERSTOOD}. Ordered by messages, not by time:
 * the outsider raises {@code go} once a has said {@code ready} (both agents are then in main).
 */
@Timeout(120)
class OutsideEventsJadeTest {

    private static final String READY = "{\"event\":\"ready\",\"block\":\"main\",\"emitter\":\"a\",\"message\":\"\"}";

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void anOutsideAgentReceivesSharedEventsAndRaisesOne() throws Exception {
        JadePlatform platform = JADE.platform();
        OutsideRequestsJadeTest.Outsider outsider = new OutsideRequestsJadeTest.Outsider();
        platform.container().acceptNewAgent("watcher", outsider).start();
        CompletableFuture<MaslCommand> run = CompletableFuture.supplyAsync(() -> MaslCommand.run("run",
                "src/test/resources/outsiders/events.masl", "--platform", "jade", "--main-host", platform.host(),
                "--main-port", String.valueOf(platform.port()), "--timeout", "60"));
        AID a = new AID("a", AID.ISLOCALNAME);
        DFAgentDescription registered = new DFAgentDescription();
        registered.setName(a);
        assertNotNull(DFService.searchUntilFound(outsider, outsider.getDefaultDF(), registered, null, 30_000),
                () -> "a registered within 30 s; the run: " + run.getNow(null));

        outsider.send(message(ACLMessage.SUBSCRIBE, a, "s1", null, null));
        assertAnswer(outsider, ACLMessage.AGREE, "s1", null);
        // a says ready (every 100 ms) once both agents are in main, where go is declared.
        assertAnswer(outsider, ACLMessage.INFORM, "s1", READY);

        outsider.send(message(ACLMessage.INFORM, a, "e1", "masl-event", "{\"event\":\"nosuch\"}"));
        assertAnswer(outsider, ACLMessage.NOT_UNDERSTOOD, "e1",
                "{\"error\":\"message: error: no agent of the mission perceives a shared event named nosuch now\"}");
        outsider.send(message(ACLMessage.INFORM, a, "e2", "masl-event", "{\"event\":\"go\",\"message\":\"now\"}"));
        assertAnswer(outsider, ACLMessage.INFORM, "s1",
                "{\"event\":\"go\",\"block\":\"main\",\"emitter\":null,\"message\":\"now\"}");
        assertAnswer(outsider, ACLMessage.INFORM, "s1",
                "{\"event\":\"done\",\"block\":\"main\",\"emitter\":\"a\",\"message\":\"both heard now\"}");

        MaslCommand done = run.get(60, TimeUnit.SECONDS);
        assertEquals(0, done.status(), done::toString);
        assertEquals("heard now\nheard now\n", done.out());
        assertEquals(Readiness.platform(platform) + "\n", done.err());
    }

    private static ACLMessage message(int performative, AID receiver, String replyWith, String conversation,
            String content) {
        ACLMessage message = new ACLMessage(performative);
        message.addReceiver(receiver);
        message.setReplyWith(replyWith);
        message.setConversationId(conversation);
        message.setLanguage("json");
        message.setOntology("masl");
        message.setContent(content);
        return message;
    }

    /** The next message but further {@code ready} events is the one expected. */
    private static void assertAnswer(OutsideRequestsJadeTest.Outsider outsider, int performative, String inReplyTo,
            String content) throws InterruptedException {
        ACLMessage answer = outsider.answers.poll(30, TimeUnit.SECONDS);
        while (answer != null && READY.equals(answer.getContent()) && !READY.equals(content)) {
            answer = outsider.answers.poll(30, TimeUnit.SECONDS);
        }
        assertNotNull(answer, "answered within 30 s");
        assertEquals(ACLMessage.getPerformative(performative), ACLMessage.getPerformative(answer.getPerformative()),
                answer::toString);
        assertEquals(inReplyTo, answer.getInReplyTo(), answer::toString);
        if (content != null) {
            assertEquals(content, answer.getContent(), answer::toString);
        }
    }
}
