package masl.jade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import masl.jade.acl.AclInvocations;
import masl.jade.testing.JadePlatformExtension;
import masl.runtime.AgentContext;
import masl.runtime.EntryDefinition;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.Mode;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
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
class ForgedMessagesTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(60);
    /** How many of the coordinator's former, sequential conversation ids a forger tries. */
    private static final int GUESSES = 20;

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
                    JadeLauncher.of(callsGated(results)).types(TestPrograms::type).place(Map.of("b", "c2")),
                    JADE.platform(), TIMEOUT);
            gate.entered().get(60, TimeUnit.SECONDS);
            AID coordinator = new AID(CoordinatorAgent.NAME, AID.ISLOCALNAME);
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
            MissionOutcome outcome = mission.get(60, TimeUnit.SECONDS);
            outcome.requireCompleted();
            assertEquals(List.of(7), results, "the body's own result");
            assertEquals("", outcome.journal());
            assertNull(System.getProperty(Detonator.MARK), "the class a forged FAILURE named was initialised");
        }
    }

    private static MaslContainer container(String name) {
        return MaslContainer.start(JadeOptions.join(JADE.platform().host(), JADE.platform().port()), name,
                className -> TestPrograms.type(new MissionProgram.AgentSpec("", className)),
                ForgedMessagesTest.class.getClassLoader(), event -> { });
    }

    private static MissionProgram callsGated(List<Integer> results) {
        return TestPrograms.of(CallsGated.MAIN, List.of(new MissionProgram.AgentSpec("b", ServiceAgent.class.getName())),
                self -> new CallsGated(self, results));
    }

    private static ACLMessage answer(AID receiver, int performative, String inReplyTo, String content) {
        ACLMessage answer = new ACLMessage(performative);
        answer.addReceiver(receiver);
        answer.setLanguage(AclInvocations.LANGUAGE);
        answer.setOntology(AclInvocations.ONTOLOGY);
        answer.setConversationId(CoordinatorAgent.BODY);
        answer.setInReplyTo(inReplyTo);
        answer.setContent(content);
        return answer;
    }

    /** In a main block, calls {@code gated()} on its body once, keeping the result. */
    static final class CallsGated extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);

        private final List<Integer> results;

        CallsGated(TestAgent self, List<Integer> results) {
            super(self);
            this.results = results;
        }

        @Override
        protected void resume(AgentContext ctx) {
            ServiceAgent body = (ServiceAgent) self;
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 3)) return;
                        continue;
                    case 1:
                        results.add(ctx.invokeSelf("gated", -1, body::gated));
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
