package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import masl.jade.platform.JadePlatform;
import masl.jade.platform.Readiness;
import masl.testing.jade.JadePlatformExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A FIPA agent from outside the mission asks an agent of the shipped type {@code Default} to
 * {@code sleep} for ten minutes while it waits for an outside invocation ({@code wait("default",
 * 10000)}), then asks it to {@code logln}. The shipped {@code Default} does not let others call
 * {@code sleep}: that request is refused, the {@code logln} ends the wait, and the mission completes
 * at once instead of being held for ten minutes.
 */
@Timeout(120)
class OutsideRequestsJadeTest {

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void anOutsiderCannotMakeADefaultAgentSleep() throws Exception {
        JadePlatform platform = JADE.platform();
        Outsider outsider = new Outsider();
        platform.container().acceptNewAgent("outsider", outsider).start();
        CompletableFuture<MaslCommand> run = CompletableFuture.supplyAsync(() -> MaslCommand.run("run",
                "src/test/resources/outsiders/waits_for_an_outsider.masl", "--platform", "jade", "--main-host",
                platform.host(), "--main-port", String.valueOf(platform.port()), "--timeout", "60"));
        DFAgentDescription[] found = DFService.searchUntilFound(outsider, outsider.getDefaultDF(), sleepService(), null,
                30_000);
        assertNotNull(found, () -> "b registered with the DF within 30 s; the run: " + run.getNow(null));
        AID b = found[0].getName();
        outsider.send(request(b, "sleep", "{\"primitive\":\"sleep\",\"args\":[600000]}"));
        outsider.send(request(b, "logln", "{\"primitive\":\"logln\",\"args\":[\"outsider\"]}"));
        Map<String, ACLMessage> answers = new HashMap<>();
        for (int i = 0; i < 2; i++) {
            ACLMessage answer = outsider.answers.poll(30, TimeUnit.SECONDS);
            assertNotNull(answer, "answered within 30 s: " + answers.keySet());
            answers.put(answer.getInReplyTo(), answer);
        }
        assertEquals(ACLMessage.REFUSE, answers.get("sleep").getPerformative(), answers.get("sleep").toString());
        assertEquals("{\"reason\":\"the permeability of b denies others invoking sleep\"}",
                answers.get("sleep").getContent());
        assertEquals(ACLMessage.INFORM, answers.get("logln").getPerformative(), answers.get("logln").toString());
        MaslCommand done = run.get(60, TimeUnit.SECONDS);
        assertEquals(0, done.status(), done::toString);
        assertEquals("outsider\ndone\n", done.out());
        assertEquals(Readiness.platform(platform) + "\n", done.err());
    }

    private static DFAgentDescription sleepService() {
        DFAgentDescription template = new DFAgentDescription();
        ServiceDescription service = new ServiceDescription();
        service.setType("masl-primitive");
        service.setName("sleep");
        template.addServices(service);
        return template;
    }

    private static ACLMessage request(AID receiver, String replyWith, String content) {
        ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
        request.addReceiver(receiver);
        request.setLanguage("json");
        request.setOntology("masl");
        request.setReplyWith(replyWith);
        request.setContent(content);
        return request;
    }

    /** A plain JADE agent outside the mission: queues the answers it gets (not the DF's, not the AMS's). */
    public static final class Outsider extends Agent {
        private static final long serialVersionUID = 1L;

        final transient BlockingQueue<ACLMessage> answers = new LinkedBlockingQueue<>();

        @Override
        protected void setup() {
            MessageTemplate notThePlatforms = MessageTemplate.not(MessageTemplate.or(
                    MessageTemplate.MatchSender(getDefaultDF()), MessageTemplate.MatchSender(getAMS())));
            addBehaviour(new CyclicBehaviour(this) {
                private static final long serialVersionUID = 1L;

                @Override
                public void action() {
                    ACLMessage message = myAgent.receive(notThePlatforms);
                    if (message == null) {
                        block();
                    } else {
                        answers.add(message);
                    }
                }
            });
        }
    }
}
