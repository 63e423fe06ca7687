package masl.runtime.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Supplier;
import masl.jade.JadeLauncher;
import masl.jade.Probe;
import masl.jade.Tallies;
import masl.jade.TestPrograms;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.Reply;
import masl.jade.placement.DeployedSource;
import masl.jade.placement.MaslContainer;
import masl.jade.placement.ProgramTranslator;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.trust.Forgeries;
import masl.jade.trust.MissionSecret;
import masl.runtime.AgentImplementation;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.testing.jade.JadePlatformExtension;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * E2 with its agents' programs deployed to containers of this JVM's platform over signed ACL: the
 * journal in-process gives; an agent's counts and writes reach another agent's real object in another
 * container; a FIPA agent's request to a deployed agent runs on its real object; a container whose
 * translation is not the coordinator's refuses before the mission starts; a coordination message
 * another agent of the platform forges is refused and said.
 */
@Timeout(180)
class DeployedInJadeTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(60);
    private static final MissionSecret SECRET = MissionSecret.generate();
    private static final String KEY = "the key of e2";
    private static final DeployedSource SOURCE = new DeployedSource("e2.masl", "// E2", Map.of(), KEY);
    private static final String E2 = "n=5\n" + "mine=1\n".repeat(5);
    private static final Supplier<MissionProgram> TALLIES = () -> new Tallies(true);

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    private static Probe forger;

    @BeforeAll
    static void startForger() throws Exception {
        forger = new Probe();
        JADE.platform().container().acceptNewAgent("deployment-forger", forger).start();
    }

    @Test
    void e2OverTwoContainersGivesTheJournalOfInProcess() throws Exception {
        try (MaslContainer d2 = container("d2", KEY); MaslContainer d3 = container("d3", KEY)) {
            MissionOutcome outcome = launcher(Map.of("a0", "d2", "a2", "d3", "a3", "d2"), line -> { })
                    .run(JADE.platform(), TIMEOUT);
            assertTrue(outcome.completed(), outcome.toString());
            assertEquals(E2, outcome.journal());
            assertEquals(List.of("a0", "a3"), d2.hostedAgents());
        }
    }

    @Test
    void anInvocationAndAnAttributeWriteOfAnAgentInAnotherContainerRunOnItsRealObject() throws Exception {
        Map<String, String> deployment = Map.of("owner", "d6", "caller", "d7");
        try (MaslContainer d6 = container("d6", KEY, TALLIES); MaslContainer d7 = container("d7", KEY, TALLIES)) {
            MissionOutcome outcome = JadeLauncher.of(TALLIES.get()).types(TestPrograms::type).deploy(deployment, SOURCE)
                    .secret(SECRET).run(JADE.platform(), TIMEOUT);
            assertTrue(outcome.completed(), outcome.toString());
            assertEquals(Tallies.COUNTS_AND_WRITES, outcome.journal());
        }
    }

    /**
     * A plain FIPA agent asks the deployed {@code owner}, by its name, to count 1,000 as the mission
     * starts: the owner serves it at a boundary, on its real object in container d8, whose counts
     * the mission's and the FIPA agent's add up on.
     */
    @Test
    void aFipaAgentInvokesADeployedAgentOnItsRealObject() throws Exception {
        Probe asker = new Probe();
        JADE.platform().container().acceptNewAgent("deployed-asker", asker).start();
        try (MaslContainer d8 = container("d8", KEY, () -> new Tallies(false))) {
            MissionOutcome outcome = JadeLauncher.of(new Tallies(false)).types(TestPrograms::type)
                    .deploy(Map.of("owner", "d8"), SOURCE).secret(SECRET).whenReady(mission -> asker.sendMessage(
                            AclInvocations.request(new AID("owner", AID.ISLOCALNAME), "count", List.of(1000), "asked")))
                    .run(JADE.platform(), TIMEOUT);
            assertTrue(outcome.completed(), outcome.toString());
            Reply answer = AclInvocations.readReply(asker.next());
            // The real object counted 1,000 on top of the caller's counts served before it (0 to 3),
            // and the owner's total says 1,003 unless the request came after its last count; a copy
            // would answer 1,000 and leave the owner's total at 3.
            int counted = answer instanceof Reply.Result result ? result.value().intValue() : -1;
            String total = outcome.journal().lines().reduce((first, last) -> last).orElse("");
            assertTrue(counted >= 1000 && counted <= 1003, answer.toString());
            assertTrue(total.equals("owner's total 1003") || counted == 1003, counted + "\n" + outcome.journal());
        }
    }

    @Test
    void aContainerWhoseTranslationIsNotTheCoordinatorsRefusesBeforeTheMission() throws Exception {
        try (MaslContainer d4 = container("d4", "another masl's key")) {
            JadeException refused = assertThrows(JadeException.class,
                    () -> launcher(Map.of("a1", "d4"), line -> { }).run(JADE.platform(), TIMEOUT));
            assertTrue(refused.getMessage().startsWith("container d4 cannot host a1: its translation of e2.masl is not"
                    + " the coordinator's"), refused.getMessage());
            assertEquals(d4.unhosted().orElseThrow(), refused.getMessage());
        }
    }

    @Test
    void aForgedArrivalIsRefused() throws Exception {
        assertForgedRefused("{\"kind\":\"call\",\"agent\":0,\"op\":\"stepBoundary\",\"pc\":3}");
    }

    @Test
    void aForgedSharedWriteIsRefused() throws Exception {
        assertForgedRefused("{\"kind\":\"call\",\"agent\":0,\"op\":\"shared-set\",\"pc\":3,\"shared\":\"0:0\","
                + "\"value\":{\"int\":99}}");
    }

    @Test
    void aForgedEventIsRefused() throws Exception {
        assertForgedRefused("{\"kind\":\"call\",\"agent\":0,\"op\":\"emit\",\"pc\":3,\"event\":\":timeout\","
                + "\"message\":\"forged\"}");
    }

    @Test
    void aForgedEntryIsRefused() throws Exception {
        assertForgedRefused("{\"kind\":\"call\",\"agent\":0,\"op\":\"leave\",\"pc\":3,\"block\":\"0\"}");
    }

    @Test
    void aForgedLabelRequestIsRefused() throws Exception {
        assertForgedRefused("{\"kind\":\"call\",\"agent\":0,\"op\":\"label-free\",\"pc\":3,\"label\":\"0.0\"}");
    }

    @Test
    void aForgedInvocationIsRefused() throws Exception {
        assertForgedRefused("{\"kind\":\"call\",\"agent\":0,\"op\":\"invoke\",\"pc\":3,\"callee\":1,"
                + "\"primitive\":\"logln\",\"args\":[{\"string\":\"forged\"}],\"call\":1}");
    }

    /** A container's record of an invocation it served between two of its agents, forged. */
    @Test
    void aForgedInvocationServedInAContainerIsRefused() throws Exception {
        assertForgedRefused("{\"kind\":\"invoked\",\"agent\":0,\"callee\":1,\"primitive\":\"logln\",\"pc\":3}");
    }

    /**
     * Before the mission starts, the forger sends {@code content} as agent a0's container would, once
     * unsigned and once signed by itself with the mission's secret (a member of the mission speaking for
     * an agent not its own): both refused and said; the mission then gives E2's journal.
     */
    private void assertForgedRefused(String content) throws Exception {
        BlockingQueue<String> problems = new LinkedBlockingQueue<>();
        try (MaslContainer d5 = container("d5", KEY)) {
            MissionOutcome outcome = launcher(Map.of("a0", "d5"), problems::add).whenReady(mission -> {
                try {
                    AID coordinator = new AID("masl-coordinator", AID.ISLOCALNAME);
                    forger.sendMessage(inform(coordinator, content));
                    String unsigned = problems.poll(20, TimeUnit.SECONDS);
                    assertTrue(unsigned != null && unsigned.startsWith("refused INFORM masl-deployed from "
                            + forger.getName()) && unsigned.endsWith(": not signed with the mission's secret"),
                            String.valueOf(unsigned));
                    forger.sendMessage(Forgeries.signedBy(SECRET, forger.getAID(), inform(coordinator, content)));
                    assertEquals("refused INFORM masl-deployed from " + forger.getName() + ": it does not come from"
                            + " the container of a0", problems.poll(20, TimeUnit.SECONDS));
                } catch (InterruptedException interrupted) {
                    throw new IllegalStateException(interrupted);
                }
            }).run(JADE.platform(), TIMEOUT);
            assertTrue(outcome.completed(), outcome.toString());
            assertEquals(E2, outcome.journal());
        }
    }

    private static ACLMessage inform(AID receiver, String content) {
        ACLMessage message = new ACLMessage(ACLMessage.INFORM);
        message.addReceiver(receiver);
        message.setLanguage(AclInvocations.LANGUAGE);
        message.setOntology(AclInvocations.ONTOLOGY);
        message.setConversationId("masl-deployed");
        message.setContent(content);
        return message;
    }

    private static JadeLauncher launcher(Map<String, String> deployment, Consumer<String> problems) {
        return JadeLauncher.of(e2()).types(TestPrograms::type).deploy(deployment, SOURCE).secret(SECRET)
                .problems(problems);
    }

    private static AgentImplementation newAgent(MissionProgram.AgentSpec spec) throws ReflectiveOperationException {
        return (AgentImplementation) Class.forName(spec.typeClassName()).getConstructor().newInstance();
    }

    private static MissionProgram e2() {
        return TestPrograms.of(E2SharedAndLocal.MAIN, 5, E2SharedAndLocal::new);
    }

    /**
     * Container {@code name} of this JVM, which "translates" E2 with the key {@code key}, and leaves the
     * platform once its mission has ended, as a container of its own JVM does (the coordinator's end
     * waits for that).
     */
    private static MaslContainer container(String name, String key) {
        return container(name, key, DeployedInJadeTest::e2);
    }

    /** Container {@code name}, as {@link #container(String, String)}, for the program {@code program} makes. */
    private static MaslContainer container(String name, String key, Supplier<MissionProgram> program) {
        MaslContainer container = MaslContainer.start(JadeOptions.join(JADE.platform().host(), JADE.platform().port()), name,
                className -> TestPrograms.type(new MissionProgram.AgentSpec("", className)),
                DeployedInJadeTest.class.getClassLoader(), event -> { }, MissionSecret.Source.of(SECRET), refusal -> { },
                source -> new ProgramTranslator.Translated(program.get(), DeployedInJadeTest::newAgent, key));
        Thread closer = new Thread(() -> {
            try {
                if (container.awaitMissionEnd(TIMEOUT)) {
                    container.close();
                }
            } catch (InterruptedException interrupted) {
                Thread.currentThread().interrupt();
            }
        }, "closes " + name);
        closer.setDaemon(true);
        closer.start();
        return container;
    }
}
