package masl.jade.placement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import jade.content.lang.sl.SLCodec;
import jade.content.onto.basic.Action;
import jade.core.AID;
import jade.domain.FIPANames;
import jade.domain.JADEAgentManagement.JADEManagementOntology;
import jade.domain.JADEAgentManagement.KillAgent;
import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.List;
import java.util.ArrayList;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import masl.jade.JadeLauncher;
import masl.jade.Probe;
import masl.jade.ServiceAgent;
import masl.jade.TestPrograms;
import masl.jade.acl.Conversations;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.trust.ForgedMessagesTest;
import masl.jade.trust.MissionSecret;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The agent of a container hosting a body leaves in order (deleted, with the body, as when
 * {@code masl container}'s own timeout closes it) while the body runs a call that does not answer, and
 * no AMS removal event comes (the container itself stays; a coordinator may miss that event anyway):
 * the call fails with {@code uncaught_exception} and its default value, as when the container's JVM
 * dies, and the mission ends instead of waiting for its timeout.
 */
@Timeout(150)
class ContainerLeavingTest {

    /** Longer than the test waits for the outcome: a mission still waiting for the call fails the test. */
    private static final Duration MISSION_TIMEOUT = Duration.ofMinutes(5);

    @Test
    void aCallToABodyWhoseContainerLeavesFailsAndTheMissionEnds() throws Exception {
        MissionSecret secret = MissionSecret.generate();
        List<Integer> results = new CopyOnWriteArrayList<>();
        // The call ignores the interrupt its body's deletion brings: it never answers, as a slow primitive would not in time.
        ServiceAgent.Gate gate = new ServiceAgent.Gate(new CompletableFuture<>(), new CompletableFuture<>() {
            @Override
            public Integer get() {
                return join();
            }
        });
        ServiceAgent.gate = gate;
        JadePlatform main = JadePlatform.start(JadeOptions.mainContainer());
        try (MaslContainer container = ForgedMessagesTest.container(main, "c2", secret)) {
            Probe ams = new Probe();
            main.container().acceptNewAgent("killer", ams).start();
            CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(JadeLauncher.of(ForgedMessagesTest.callsGated(results))
                    .types(TestPrograms::type).place(Map.of("b", "c2")).secret(secret), main, MISSION_TIMEOUT);
            gate.entered().get(60, TimeUnit.SECONDS);
            ams.sendMessage(killing(ams, Conversations.containerAgent("c2")));
            MissionOutcome outcome = mission.get(100, TimeUnit.SECONDS);
            outcome.requireCompleted();
            assertEquals(List.of(-1), results, "the default value of the call");
        } finally {
            gate.result().complete(0);
            main.close();
        }
    }

    /**
     * A container closing while it creates its bodies (JADE interrupts its agent's thread, as
     * {@code masl container}'s own timeout does): the coordinator's placement fails saying so in words.
     */
    @Test
    @Tag("slow") // the mission's end waits 10 s for the container it ended to leave, which it does only after
    void aContainerClosingWhilePlacedSaysSoInWords() throws Exception {
        MissionSecret secret = MissionSecret.generate();
        JadePlatform main = JadePlatform.start(JadeOptions.mainContainer());
        // The interrupt its closing brings, on the container agent's thread while it makes the body.
        try (MaslContainer container = MaslContainer.start(JadeOptions.join(main.host(), main.port()), "c2",
                className -> {
                    Thread.currentThread().interrupt();
                    return TestPrograms.type(new MissionProgram.AgentSpec("", className));
                }, ContainerLeavingTest.class.getClassLoader(), event -> { }, MissionSecret.Source.of(secret),
                refusal -> { })) {
            JadeException failed = assertThrows(JadeException.class, () -> JadeLauncher.of(
                    ForgedMessagesTest.callsGated(new ArrayList<>())).types(TestPrograms::type).place(Map.of("b", "c2"))
                    .secret(secret).run(main, MISSION_TIMEOUT));
            assertEquals("container c2 cannot host b: the container closed before its bodies were placed",
                    failed.getMessage());
        } finally {
            main.close();
        }
    }

    /** The request asking the AMS to delete agent {@code name}, as JADE's own tools send it. */
    private static ACLMessage killing(Probe sender, String name) throws Exception {
        sender.getContentManager().registerLanguage(new SLCodec(), FIPANames.ContentLanguage.FIPA_SL);
        sender.getContentManager().registerOntology(JADEManagementOntology.getInstance());
        KillAgent kill = new KillAgent();
        kill.setAgent(new AID(name, AID.ISLOCALNAME));
        ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
        request.addReceiver(sender.getAMS());
        request.setLanguage(FIPANames.ContentLanguage.FIPA_SL);
        request.setOntology(JADEManagementOntology.NAME);
        sender.getContentManager().fillContent(request, new Action(sender.getAMS(), kill));
        return request;
    }
}
