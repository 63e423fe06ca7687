package masl.jade.placement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.core.AID;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import masl.jade.BodyContainerMain;
import masl.jade.DfEntries;
import masl.jade.JadeLauncher;
import masl.jade.Probe;
import masl.jade.ServiceAgent;
import masl.jade.TestPrograms;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.Reply;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.testing.jade.JadePlatformExtension;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A plain FIPA agent of the main container invokes a MASL agent whose body is in another JVM: the
 * body relays the request to the coordinator, which filters it by the agent's state as an
 * <em>other</em> and has it run on the body; the answer comes from the body.
 */
@Timeout(120)
@Tag("slow")
class TwoJvmFipaRequestTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(60);

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    private static Probe probe;

    @BeforeAll
    static void startProbe() throws Exception {
        probe = new Probe();
        JADE.platform().container().acceptNewAgent("probe", probe).start();
    }

    @Test
    void aRequestToABodyInAnotherJvmIsFilteredByTheAgentsStateThere() throws Exception {
        TestPrograms.Signals signals = new TestPrograms.Signals();
        MissionProgram program = TestPrograms.of(null,
                List.of(new MissionProgram.AgentSpec("b", ServiceAgent.class.getName())),
                self -> new TestPrograms.ClosesWhenAsked(self, signals));
        try (SecondJvm container = BodyContainerMain.start(JADE.platform(), "c2")) {
            CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(
                    JadeLauncher.of(program).types(TestPrograms::type).place(Map.of("b", "c2"))
                            .secret(BodyContainerMain.SECRET),
                    JADE.platform(),
                    TIMEOUT);
            try {
                DFAgentDescription[] found = DFService.searchUntilFound(probe, probe.getDefaultDF(),
                        DfEntries.service(null, DfEntries.PRIMITIVE_SERVICE, "release"), null, 30_000);
                assertTrue(found != null && found.length == 1, "b registered with the DF within 30 s");
                ACLMessage sum = invoke("add", List.of(2, 3), "r1");
                assertEquals(ACLMessage.INFORM, sum.getPerformative(), sum.getContent());
                assertEquals("{\"result\":5}", sum.getContent());
                assertEquals("b", sum.getSender().getLocalName());
                assertEquals(ACLMessage.INFORM, invoke("log", List.of("before "), "r2").getPerformative());
                signals.closeRequested().complete(null);
                signals.closed().get(20, TimeUnit.SECONDS);
                ACLMessage refused = invoke("log", List.of("denied "), "r3");
                assertEquals(ACLMessage.REFUSE, refused.getPerformative());
                assertEquals(new Reply.Refused("the permeability of b denies others invoking log"),
                        AclInvocations.readReply(refused));
            } finally {
                signals.closeRequested().complete(null);
                signals.finishRequested().complete(null);
            }
            MissionOutcome outcome = mission.get();
            assertTrue(outcome.completed(), outcome + "\n" + container.output());
            assertEquals("before ", outcome.journal());
            assertTrue(container.assertEndsByItself().contains("hosted b\n"));
        }
    }

    private static ACLMessage invoke(String primitive, List<?> args, String replyWith) throws InterruptedException {
        probe.sendMessage(AclInvocations.request(new AID("b", AID.ISLOCALNAME), primitive, args, replyWith));
        ACLMessage answer = probe.next();
        assertEquals(replyWith, answer.getInReplyTo());
        return answer;
    }
}
