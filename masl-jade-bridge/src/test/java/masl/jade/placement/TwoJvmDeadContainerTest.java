package masl.jade.placement;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import masl.jade.BodyContainerMain;
import masl.jade.JadeLauncher;
import masl.jade.ServiceAgent;
import masl.jade.TestPrograms;
import masl.runtime.AgentContext;
import masl.runtime.EntryDefinition;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.Mode;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import masl.testing.jade.JadePlatformExtension;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The JVM hosting an agent's body is killed while the agent's program calls it: the call fails
 * with {@code uncaught_exception} and its default value once the AMS reports the container removed,
 * so the mission goes on and ends long before its timeout.
 */
@Timeout(120)
@Tag("slow")
class TwoJvmDeadContainerTest {

    private static final Duration MISSION_TIMEOUT = Duration.ofSeconds(90);

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void aCallToABodyWhoseJvmIsKilledFailsAndTheMissionEnds() throws Exception {
        CompletableFuture<Void> calling = new CompletableFuture<>();
        List<Integer> results = new CopyOnWriteArrayList<>();
        MissionProgram program = TestPrograms.of(CallsHangTwice.MAIN,
                List.of(new MissionProgram.AgentSpec("b", ServiceAgent.class.getName())),
                self -> new CallsHangTwice(self, calling, results));
        try (SecondJvm container = BodyContainerMain.start(JADE.platform(), "c2")) {
            CompletableFuture<MissionOutcome> mission = TestPrograms.runInBackground(
                    JadeLauncher.of(program).types(TestPrograms::type).place(Map.of("b", "c2"))
                            .secret(BodyContainerMain.SECRET),
                    JADE.platform(),
                    MISSION_TIMEOUT);
            calling.get(60, TimeUnit.SECONDS);
            container.kill();
            MissionOutcome outcome = mission.get(60, TimeUnit.SECONDS);
            outcome.requireCompleted();
            assertEquals(List.of(-1, -1), results, "the default value of each call");
            assertEquals("", outcome.journal());
        }
    }

    /**
     * In a main block, calls {@code hang()} on its body twice, keeping each result: one call in
     * progress when the body's JVM dies, one after. (Its body's {@code log} would fail as well.)
     */
    static final class CallsHangTwice extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);

        private final CompletableFuture<Void> calling;
        private final List<Integer> results;

        CallsHangTwice(TestAgent self, CompletableFuture<Void> calling, List<Integer> results) {
            super(self);
            this.calling = calling;
            this.results = results;
        }

        @Override
        protected void resume(AgentContext ctx) {
            ServiceAgent body = (ServiceAgent) self;
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 4)) return;
                        continue;
                    case 1:
                        calling.complete(null);
                        results.add(ctx.invokeSelf("hang", -1, body::hang));
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2:
                        results.add(ctx.invokeSelf("hang", -1, body::hang));
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3:
                        if (!leave(ctx, MAIN, 4)) return;
                        continue;
                    case 4:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }
}
