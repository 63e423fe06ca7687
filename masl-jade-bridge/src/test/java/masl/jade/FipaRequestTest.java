package masl.jade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.node.IntNode;
import jade.core.AID;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.Reply;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.testing.jade.JadePlatformExtension;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A plain FIPA agent (test code using the JADE API only) invokes the primitives of a MASL agent
 * running inside JADE, with {@code REQUEST}s, and gets every kind of answer.
 */
@Timeout(120)
class FipaRequestTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(60);

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    private static Probe probe;
    /** The MASL agent; an AID by local name needs the platform's name, so it is made after the start. */
    private static AID b;
    private static int conversations;

    @BeforeAll
    static void startProbe() throws Exception {
        probe = new Probe();
        JADE.platform().container().acceptNewAgent("probe", probe).start();
        b = new AID("b", AID.ISLOCALNAME);
    }

    /** In-process the watchdog would call this busy-wait a deadlock; inside JADE a request may end it. */
    @Test
    void aRequestEndsABusyWaitingAgent() throws Exception {
        MissionProgram program = TestPrograms.of(null,
                List.of(new MissionProgram.AgentSpec("b", ServiceAgent.class.getName())),
                TestPrograms.BusyUntilReleased::new);
        CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(
                JadeLauncher.of(program).types(TestPrograms::type), JADE.platform(), TIMEOUT);
        awaitRegistered();
        assertEquals(ACLMessage.INFORM, invoke("release", List.of()).getPerformative());
        MissionOutcome outcome = mission.get();
        assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
        assertEquals("released", outcome.journal());
    }

    @Test
    void primitivesAnswerInformWithTheirResult() throws Exception {
        MissionOutcome outcome = runWhile(() -> {
            ACLMessage logged = invoke("log", List.of("hello from FIPA"));
            assertEquals(ACLMessage.INFORM, logged.getPerformative());
            assertEquals("{\"result\":null}", logged.getContent());
            ACLMessage sum = invoke("add", List.of(2, 3));
            assertEquals(new Reply.Result(new IntNode(5)),
                    AclInvocations.readReply(sum));
            assertEquals("json", sum.getLanguage());
            assertEquals("masl", sum.getOntology());
        });
        assertEquals("hello from FIPA", outcome.journal());
    }

    @Test
    void aPrimitiveThatThrowsOrAResultThatCannotBeWrittenAnswersFailure() throws Exception {
        runWhile(() -> {
            ACLMessage failed = invoke("divide", List.of(1, 0));
            assertEquals(ACLMessage.FAILURE, failed.getPerformative());
            assertEquals(new Reply.Failed("java.lang.ArithmeticException", "/ by zero"),
                    AclInvocations.readReply(failed));
            assertEquals(new Reply.Failed("java.lang.IllegalStateException", "no text for this"),
                    AclInvocations.readReply(invoke("unwritable", List.of())));
            assertEquals(ACLMessage.INFORM, invoke("nop", List.of()).getPerformative(), "the agent still serves");
        });
    }

    /**
     * An outsider invokes a primitive that would never return: past the mission's call timeout it is
     * interrupted and answered {@code FAILURE} {@code TimeoutException}, and the agent, whose program
     * waited while the call was served on its behalf, goes on (serves the next request, completes).
     */
    @Test
    void anOutsidersCallRunsWithinTheCallTimeoutAndTheAgentGoesOn() throws Exception {
        ServiceAgent.Gate gate = new ServiceAgent.Gate();
        ServiceAgent.gate = gate;
        MissionProgram program = TestPrograms.of(null,
                List.of(new MissionProgram.AgentSpec("b", ServiceAgent.class.getName())),
                TestPrograms.UntilReleased::new);
        CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(
                JadeLauncher.of(program).types(TestPrograms::type).callTimeout(Duration.ofMillis(500)),
                JADE.platform(), TIMEOUT);
        awaitRegistered();
        try {
            ACLMessage late = invoke("gated", List.of());
            assertEquals(ACLMessage.FAILURE, late.getPerformative(), late.getContent());
            assertEquals(new Reply.Failed("java.util.concurrent.TimeoutException", "gated ran past 500 ms, the limit"
                    + " of a call from outside the mission, and was interrupted"), AclInvocations.readReply(late));
            assertTrue(gate.entered().isDone(), "it ran");
            assertEquals(new Reply.Result(new IntNode(5)), AclInvocations.readReply(invoke("add", List.of(2, 3))));
        } finally {
            invoke("release", List.of());
        }
        assertTrue(mission.get().completed());
    }

    /**
     * The check: {@code log} answers {@code INFORM}; once the agent's program has set a state
     * denying others, the same request answers {@code REFUSE} and does not run; invalid JSON answers
     * {@code NOT_UNDERSTOOD} whatever the state.
     */
    @Test
    void afterTheAgentSetsAStateDenyingOthersTheSameRequestIsRefused() throws Exception {
        TestPrograms.Signals signals = new TestPrograms.Signals();
        MissionProgram program = TestPrograms.of(null,
                List.of(new MissionProgram.AgentSpec("b", ServiceAgent.class.getName())),
                self -> new TestPrograms.ClosesWhenAsked(self, signals));
        CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(
                JadeLauncher.of(program).types(TestPrograms::type), JADE.platform(), TIMEOUT);
        try {
            awaitRegistered();
            assertEquals(ACLMessage.INFORM, invoke("log", List.of("before ")).getPerformative());
            signals.closeRequested().complete(null);
            signals.closed().get(20, TimeUnit.SECONDS);
            ACLMessage refused = invoke("log", List.of("denied "));
            assertEquals(ACLMessage.REFUSE, refused.getPerformative());
            assertEquals(new Reply.Refused("the permeability of b denies others invoking log"),
                    AclInvocations.readReply(refused));
            assertNotUnderstood("content:1:20: error: malformed JSON: Unexpected character ('}' (code 125)): "
                    + "was expecting double-quote to start field name",
                    raw(ACLMessage.REQUEST, "{\"primitive\":\"log\",}"));
        } finally {
            signals.closeRequested().complete(null);
            signals.finishRequested().complete(null);
        }
        MissionOutcome outcome = mission.get();
        assertTrue(outcome.completed(), outcome::toString);
        assertEquals("before ", outcome.journal());
    }

    @Test
    void malformedAndUnknownRequestsAnswerNotUnderstood() throws Exception {
        runWhile(() -> {
            assertNotUnderstood("content:1:20: error: malformed JSON: Unexpected character ('}' (code 125)): "
                    + "was expecting double-quote to start field name",
                    raw(ACLMessage.REQUEST, "{\"primitive\":\"log\",}"));
            assertNotUnderstood("content:1:14: error: unknown primitive \"fly\": ServiceAgent has getProxyID, nop, "
                    + "log, logln, add, divide, unwritable, release, hang, gated", raw(ACLMessage.REQUEST, "{\"primitive\":\"fly\"}"));
            assertNotUnderstood("content:1:14: error: int add(int, int) takes 2 arguments, got 1",
                    raw(ACLMessage.REQUEST, "{\"primitive\":\"add\",\"args\":[1]}"));
            assertNotUnderstood("content:1:30: error: argument 2 of add: expected an int, got \"two\"",
                    raw(ACLMessage.REQUEST, "{\"primitive\":\"add\",\"args\":[1,\"two\"]}"));
            assertNotUnderstood("message: error: performative INFORM is not understood: a MASL agent answers REQUEST"
                    + " (invocations), QUERY_REF (attributes), SUBSCRIBE and CANCEL (events) and INFORM masl-event",
                    raw(ACLMessage.INFORM, "{\"primitive\":\"nop\"}"));
            // A NOT_UNDERSTOOD is never answered (two agents would echo forever): the next answer
            // the probe gets is the one to the request after it.
            probe.sendMessage(request(ACLMessage.NOT_UNDERSTOOD, "{}", "ignored"));
            assertEquals(ACLMessage.INFORM, invoke("nop", List.of()).getPerformative());
        });
    }

    @Test
    void theAgentIsRegisteredWithTheDfWhileItsMissionRuns() throws Exception {
        runWhile(() -> {
            assertEquals(List.of("b"), providers(DfEntries.PRIMITIVE_SERVICE, "divide"));
            assertEquals(List.of("b"), providers(DfEntries.TYPE_SERVICE, "ServiceAgent"));
            DFAgentDescription entry = DFService.search(probe, template(DfEntries.TYPE_SERVICE, "ServiceAgent"))[0];
            Iterator<?> services = entry.getAllServices();
            while (services.hasNext()) {
                ServiceDescription service = (ServiceDescription) services.next();
                assertEquals(List.of("fipa-request"), list(service.getAllProtocols()), service::toString);
                assertEquals(List.of("json"), list(service.getAllLanguages()), service::toString);
                assertEquals(List.of("masl"), list(service.getAllOntologies()), service::toString);
            }
        });
        assertEquals(List.of(), providers(DfEntries.PRIMITIVE_SERVICE, "divide"), "deregistered at the end");
    }

    @Test
    void queryRefReadsAnAttributeOnlyIfThePermeabilityLetsOthersRead() throws Exception {
        runWhile(() -> {
            ACLMessage battery = raw(ACLMessage.QUERY_REF, "{\"attribute\":\"battery\"}");
            assertEquals(ACLMessage.INFORM, battery.getPerformative(), battery::toString);
            assertEquals("{\"result\":80}", battery.getContent());
            ACLMessage secret = raw(ACLMessage.QUERY_REF, "{\"attribute\":\"secret\"}");
            assertEquals(ACLMessage.REFUSE, secret.getPerformative(), secret::toString);
            assertEquals("{\"reason\":\"the permeability of b denies others reading secret\"}", secret.getContent());
            assertNotUnderstood("content:1:1: error: b (ServiceAgent) has no attribute fuel",
                    raw(ACLMessage.QUERY_REF, "{\"attribute\":\"fuel\"}"));
            assertNotUnderstood("content:1:1: error: expected {\"attribute\": name}", raw(ACLMessage.QUERY_REF, "[]"));
        });
    }

    private static List<Object> list(Iterator<?> values) {
        List<Object> list = new ArrayList<>();
        values.forEachRemaining(list::add);
        return list;
    }

    /** What the test does while the mission runs; may throw. */
    @FunctionalInterface
    private interface Exchange {
        void run() throws Exception;
    }

    /**
     * Runs a mission of one agent {@code b} that waits until released, does {@code exchange} with it
     * from the probe, then releases it; the mission must complete.
     */
    private MissionOutcome runWhile(Exchange exchange) throws Exception {
        MissionProgram program = TestPrograms.of(null,
                List.of(new MissionProgram.AgentSpec("b", ServiceAgent.class.getName())),
                TestPrograms.UntilReleased::new);
        CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(
                JadeLauncher.of(program).types(TestPrograms::type), JADE.platform(), TIMEOUT);
        awaitRegistered();
        try {
            exchange.run();
        } finally {
            invoke("release", List.of());
        }
        MissionOutcome outcome = mission.get();
        assertTrue(outcome.completed(), outcome::toString);
        return outcome;
    }

    /**
     * Waits until {@code b} is registered (it exists, and its requests are served from then on):
     * {@code searchUntilFound} subscribes to the DF and returns on the notification.
     */
    private static void awaitRegistered() throws Exception {
        DFAgentDescription[] found = DFService.searchUntilFound(probe, probe.getDefaultDF(),
                template(DfEntries.PRIMITIVE_SERVICE, "release"), null, 20_000);
        assertTrue(found != null && found.length == 1, "b registered with the DF within 20 s");
    }

    private static List<String> providers(String serviceType, String serviceName) throws Exception {
        List<String> names = new ArrayList<>();
        for (DFAgentDescription found : DFService.search(probe, template(serviceType, serviceName))) {
            names.add(found.getName().getLocalName());
        }
        return names;
    }

    private static DFAgentDescription template(String serviceType, String serviceName) {
        DFAgentDescription template = new DFAgentDescription();
        ServiceDescription service = new ServiceDescription();
        service.setType(serviceType);
        service.setName(serviceName);
        template.addServices(service);
        return template;
    }

    private static ACLMessage invoke(String primitive, List<?> args) throws InterruptedException {
        String replyWith = "r" + (++conversations);
        probe.sendMessage(AclInvocations.request(b, primitive, args, replyWith));
        ACLMessage answer = probe.next();
        assertEquals(replyWith, answer.getInReplyTo());
        return answer;
    }

    private static ACLMessage raw(int performative, String content) throws InterruptedException {
        String replyWith = "r" + (++conversations);
        probe.sendMessage(request(performative, content, replyWith));
        ACLMessage answer = probe.next();
        assertEquals(replyWith, answer.getInReplyTo());
        return answer;
    }

    private static ACLMessage request(int performative, String content, String replyWith) {
        ACLMessage message = new ACLMessage(performative);
        message.addReceiver(b);
        message.setContent(content);
        message.setReplyWith(replyWith);
        return message;
    }

    private static void assertNotUnderstood(String error, ACLMessage answer) throws Exception {
        assertEquals(ACLMessage.NOT_UNDERSTOOD, answer.getPerformative());
        assertEquals(new Reply.NotUnderstood(error), AclInvocations.readReply(answer));
    }
}
