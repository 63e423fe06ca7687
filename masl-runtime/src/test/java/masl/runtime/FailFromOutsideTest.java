package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * An agent failed from outside its program while parked at a barrier (a deployed agent whose container
 * is lost) dies at once: it leaves its block, the barrier and the block's exit stop waiting for it,
 * and the others go on.
 */
@Timeout(60)
class FailFromOutsideTest {

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    private static final IllegalStateException LOST = new IllegalStateException("its container is gone");

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anAgentParkedAtABarrierFailedFromOutsideLeavesAndTheOthersGoOn(Driver driver) throws Exception {
        TestAgent parked = new TestAgent();
        AtomicReference<Mission> mission = new AtomicReference<>();
        MemoryTrace trace = new MemoryTrace();
        CompletableFuture<Void> died = new CompletableFuture<>();
        mission.set(Mission.builder().main(MAIN).scheduler(driver.newScheduler()).trace(event -> {
            trace.record(event);
            if (event instanceof TraceEvent.AgentFailed) {
                died.complete(null);
            }
        }).agent("parked", parked, self -> new StepsForever(self))
                .agent("failer", new TestAgent(), self -> new FailsTheOther(self, () -> mission.get().agentOf(parked), died))
                .build());
        MissionOutcome outcome = mission.get().run(Duration.ofSeconds(30));

        assertEquals(MissionOutcome.Status.FAILED, outcome.status(), outcome::toString);
        assertEquals("went on\n", outcome.journal());
        List<TraceEvent.AgentFailed> failed = trace.events(TraceEvent.AgentFailed.class);
        assertEquals(1, failed.size(), failed::toString);
        assertEquals(0, failed.get(0).agent());
        assertEquals(String.valueOf(LOST), failed.get(0).cause());
        assertEquals(1, trace.events(TraceEvent.Left.class).stream()
                .filter(left -> left.agent() == 0 && left.cause() == LeaveCause.FAILED).count(), trace.events()::toString);
    }

    /** {@code synchronous entry main (true) { while (true) { step } }}: parked at each step's barrier. */
    private static final class StepsForever extends CompactProgram {
        StepsForever(TestAgent self) {
            super(self);
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 1)) return;
                        continue;
                    case 1:
                        if (!step(ctx, 1)) return;
                        continue;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /**
     * In {@code main}, waits (polling with sleeps, arriving at no barrier) until the other agent is
     * parked, which can only be at the barrier this agent never arrives at; fails it from outside,
     * waits until it has died, still arriving at no barrier, says it went on, and leaves.
     */
    private static final class FailsTheOther extends CompactProgram {
        private final Supplier<Agent> other;
        private final CompletableFuture<Void> died;

        FailsTheOther(TestAgent self, Supplier<Agent> other, CompletableFuture<Void> died) {
            super(self);
            this.other = other;
            this.died = died;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        if (!arrive(ctx, MAIN, true, 1, 3)) return;
                        continue;
                    case 1:
                        if (!other.get().isIdle()) {
                            if (!ctx.sleep(1)) return;
                            continue;
                        }
                        other.get().failFromOutside(LOST);
                        pc = 2;
                        if (!ctx.await(died)) return;
                        continue;
                    case 2:
                        self.logln("went on");
                        if (!leave(ctx, MAIN, 3)) return;
                        continue;
                    case 3:
                        pc = 4;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
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
