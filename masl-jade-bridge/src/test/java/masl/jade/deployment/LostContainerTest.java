package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import masl.jade.TestPrograms;
import masl.runtime.AgentContext;
import masl.runtime.EntryDefinition;
import masl.runtime.MissionOutcome;
import masl.runtime.Mode;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.TraceEvent;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A deployed agent whose step is suspended in the mission when its container is lost fails then, not
 * when something resumes it: here {@code a0} (container {@code c2}) waits at the exit barrier of
 * {@code main}, and {@code a1} (in the mission's JVM) cuts {@code c2}'s wires and goes on only once
 * {@code a0} has failed, after which the barrier lets {@code a1} out alone.
 */
@Timeout(60)
class LostContainerTest {

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);

    @Test
    void anAgentParkedAtABarrierFailsWhenItsContainerIsLost() throws Exception {
        CompletableFuture<Void> waitingOut = new CompletableFuture<>();
        CompletableFuture<String> failed = new CompletableFuture<>();
        DeployedInMemory.Wires wires = new DeployedInMemory.Wires();
        InMemoryDeployment.Run run = InMemoryDeployment.run(
                () -> TestPrograms.of(MAIN, 2, self -> new CutsItsPeer(self, wires, waitingOut, failed)),
                Map.of("a0", "c2"), event -> {
                    if (event instanceof TraceEvent.WaitingOut out && out.agent() == 0) {
                        waitingOut.complete(null);
                    } else if (event instanceof TraceEvent.AgentFailed agentFailed && agentFailed.agent() == 0) {
                        failed.complete(agentFailed.cause());
                    }
                }, wires, Duration.ofSeconds(30));
        assertEquals(MissionOutcome.Status.FAILED, run.outcome().status(), run.outcome().toString());
        assertEquals("a1 went on\n", run.outcome().journal());
        assertEquals(ContainerLostException.class.getName() + ": the container c2 is gone", failed.join());
    }

    /**
     * {@code synchronous entry main (true) { … }}: {@code a0} leaves at once; {@code a1} waits until
     * {@code a0} waits out, cuts the wires of its container, waits until {@code a0} has failed, says so
     * and leaves.
     */
    private static final class CutsItsPeer extends CompactProgram {
        private final DeployedInMemory.Wires wires;
        private final CompletableFuture<Void> waitingOut;
        private final CompletableFuture<String> failed;

        CutsItsPeer(TestAgent self, DeployedInMemory.Wires wires, CompletableFuture<Void> waitingOut,
                CompletableFuture<String> failed) {
            super(self);
            this.wires = wires;
            this.waitingOut = waitingOut;
            this.failed = failed;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 5)) return;
                        continue;
                    case 1:
                        pc = ctx.proxyId() == 0 ? 4 : 2;
                        if (pc == 2 && !ctx.await(waitingOut)) return;
                        continue;
                    case 2:
                        wires.cut("c2");
                        pc = 3;
                        if (!ctx.await(failed)) return;
                        continue;
                    case 3:
                        self.logln("a1 went on");
                        pc = 4;
                        continue;
                    case 4:
                        if (!leave(ctx, MAIN, 5)) return;
                        continue;
                    case 5:
                        pc = 6;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                        continue;
                    case 6:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }
}
