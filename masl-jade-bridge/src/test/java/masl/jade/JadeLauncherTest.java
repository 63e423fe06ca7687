package masl.jade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.trust.ForgedMessagesTest;
import masl.runtime.AgentContext;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import masl.testing.jade.JadePlatformExtension;
import masl.testing.jade.ThreadSnapshot;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The launcher's own platform, its outcomes other than completion, and what it refuses to run. A
 * test that uses {@link #jade} has a platform of its own.
 */
@Timeout(120)
class JadeLauncherTest {

    private static final MissionProgram WAITER = TestPrograms.of(null,
            List.of(new MissionProgram.AgentSpec("w", ServiceAgent.class.getName())), TestPrograms.UntilReleased::new);

    @RegisterExtension
    final JadePlatformExtension jade = new JadePlatformExtension();

    @Test
    void aMissionOnItsOwnPlatformLeavesNoThreadBehind() throws Exception {
        ThreadSnapshot before = ThreadSnapshot.take();
        StringWriter journal = new StringWriter();
        MissionProgram program = TestPrograms.of(null, 2, self -> new CompactProgram(self) {
            @Override
            protected void resume(AgentContext ctx) {
                self.logln("agent " + self.getProxyID());
                ctx.finish();
            }
        });
        MissionOutcome outcome = JadeLauncher.of(program).types(TestPrograms::type).journal(journal)
                .run(JadeOptions.mainContainer(), Duration.ofSeconds(30));
        assertEquals(MissionOutcome.Status.COMPLETED, outcome.status());
        assertEquals(List.of("agent 0", "agent 1"), outcome.journal().lines().sorted().toList());
        assertEquals(outcome.journal(), journal.toString(), "the journal is written through to the sink");
        assertEquals(List.of(), before.startedSince());
    }

    /** {@code --call-timeout} inside JADE bounds the mission's own calls as in-process: default value, the mission goes on. */
    /**
     * An agent that polls an accessor in an empty {@code while} never parks: its driver must still see
     * the mission's end, or its thread outlives the mission (and JADE's shutdown waits for it in vain).
     */
    @Test
    void anAgentSpinningInALoopEndsWithTheMissionsTimeoutAndLeavesNoThreadBehind() throws Exception {
        ThreadSnapshot before = ThreadSnapshot.take();
        MissionProgram program = TestPrograms.of(null, 1, self -> new CompactProgram(self) {
            @Override
            protected void resume(AgentContext ctx) {
                // while (.getProxyID() == 0) {}: never true, never a busy-wait that parks (it invokes a primitive)
                while (ctx.invokeSelf("getProxyID", -1, self::getProxyID) == 0) {
                    if (!ctx.loopIteration()) {
                        return;
                    }
                }
                ctx.finish();
            }
        });
        MissionOutcome outcome = JadeLauncher.of(program).types(TestPrograms::type)
                .run(JadeOptions.mainContainer(), Duration.ofMillis(500));
        assertEquals(MissionOutcome.Status.TIMED_OUT, outcome.status());
        assertTrue(outcome.report().startsWith("agent a0 (0) at pc"), outcome.report());
        assertEquals(List.of(), before.startedSince());
    }

    @Test
    void aCallTimeoutBoundsTheMissionsOwnCalls() throws Exception {
        ServiceAgent.gate = new ServiceAgent.Gate();
        List<Integer> results = new CopyOnWriteArrayList<>();
        MissionProgram program = TestPrograms.of(ForgedMessagesTest.CallsOnce.MAIN,
                List.of(new MissionProgram.AgentSpec("g", ServiceAgent.class.getName())),
                self -> new ForgedMessagesTest.CallsOnce(self, results, "gated", body -> body::gated));
        MissionOutcome outcome = JadeLauncher.of(program).types(TestPrograms::type).callTimeout(Duration.ofMillis(300))
                .run(jade.platform(), Duration.ofSeconds(60));
        outcome.requireCompleted();
        assertEquals(List.of(-1), results, "the default value of the call that ran past the timeout");
    }

    @Test
    void aMissionThatTimesOutEndsAndItsAgentsAreDeleted() throws Exception {
        JadePlatform platform = jade.platform();
        MissionOutcome outcome = JadeLauncher.of(WAITER).types(TestPrograms::type)
                .run(platform, Duration.ofMillis(300));
        assertEquals(MissionOutcome.Status.TIMED_OUT, outcome.status());
        assertTrue(outcome.report().contains("agent w (0)"), outcome.report());
        // The name is free again: the same mission can run at once, and be released this time.
        ServiceAgent[] released = new ServiceAgent[1];
        MissionOutcome again = JadeLauncher.of(WAITER).types(TestPrograms::type)
                .implementations(spec -> {
                    released[0] = new ServiceAgent();
                    released[0].release();
                    return released[0];
                })
                .run(platform, Duration.ofSeconds(30));
        assertEquals(MissionOutcome.Status.COMPLETED, again.status());
    }

    @Test
    void theMissionHandedOverWhenReadyCanBeStopped() throws Exception {
        MissionOutcome outcome = JadeLauncher.of(WAITER).types(TestPrograms::type).whenReady(Mission::stop)
                .run(jade.platform(), Duration.ofSeconds(30));
        assertEquals(MissionOutcome.Status.STOPPED, outcome.status());
    }

    @Test
    void anAgentNameTakenOnThePlatformIsReported() throws Exception {
        JadePlatform platform = jade.platform();
        platform.container().acceptNewAgent("w", new Probe()).start();
        JadeException failure = assertThrows(JadeException.class,
                () -> JadeLauncher.of(WAITER).types(TestPrograms::type).run(platform, Duration.ofSeconds(30)));
        assertEquals("cannot create JADE agent w (is the name taken on the platform?)", failure.getMessage());
    }

    @Test
    void anImplementationLackingAPrimitiveOfItsTypeIsReportedBeforeAnyAgentStarts() {
        MissionProgram program = TestPrograms.of(null,
                List.of(new MissionProgram.AgentSpec("w", ServiceAgent.class.getName())),
                TestPrograms.UntilReleased::new);
        JadeException failure = assertThrows(JadeException.class, () -> JadeLauncher.of(program)
                .types(TestPrograms::type)
                .implementations(spec -> new TestAgent())
                .run((JadePlatform) null, Duration.ofSeconds(30)));
        assertEquals("masl.runtime.testing.TestAgent has no public method int add(int, int) that ServiceAgent "
                + "declares", failure.getMessage());
    }

    @Test
    void aProgramMustMakeItsAgentsThroughTheFactory() {
        MissionProgram bypassing = new MissionProgram() {
            @Override
            public List<AgentSpec> agents() {
                return WAITER.agents();
            }

            @Override
            public Mission.Builder configure(Mission.Builder builder,
                    ImplementationFactory implementations) {
                return builder.agent("w", new ServiceAgent(), TestPrograms.UntilReleased::new);
            }
        };
        IllegalStateException failure = assertThrows(IllegalStateException.class, () -> JadeLauncher.of(bypassing)
                .types(TestPrograms::type).run((JadePlatform) null, Duration.ofSeconds(1)));
        assertTrue(failure.getMessage().endsWith("declares 1 agents but made 0 through the implementation factory"),
                failure.getMessage());
    }

    @Test
    void typesAreRequired() {
        assertThrows(IllegalStateException.class,
                () -> JadeLauncher.of(WAITER).run((JadePlatform) null, Duration.ofSeconds(1)));
    }
}
