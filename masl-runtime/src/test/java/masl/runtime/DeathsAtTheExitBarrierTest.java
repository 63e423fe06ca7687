package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
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
 * Members of a synchronous block whose programs die while the others wait out at its exit barrier
 * (§6.3): each death leaves the block, and the last one lets the waiting-out members go, as one
 * step, in the order they arrived at the barrier, whichever order the deaths came in.
 */
@Timeout(120)
class DeathsAtTheExitBarrierTest {

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
    private static final int AGENTS = 7;
    private static final int RUNS = 10;

    /** Even agents wait out at once; odd ones take one step, then their programs die. */
    private static final class HalfDie extends CompactProgram {
        HalfDie(TestAgent self) {
            super(self);
        }

        @Override
        protected void resume(AgentContext ctx) {
            boolean dies = self.getProxyID() % 2 == 1;
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 4)) return; continue;
                    case 1:
                        if (dies) {
                            if (!step(ctx, 2)) return;
                        } else if (!leave(ctx, MAIN, 3)) {
                            return;
                        }
                        continue;
                    case 2: throw new AssertionError("dies while others wait out");
                    case 3: if (!endOf(ctx, MAIN.sequence(), 4)) return; continue;
                    case 4: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void theLastDeathLetsTheWaitingOutGoInTheirArrivalOrder(Driver driver) throws Exception {
        for (int run = 0; run < RUNS; run++) {
            MemoryTrace trace = new MemoryTrace();
            Mission.Builder builder = Mission.builder().main(MAIN);
            for (int i = 0; i < AGENTS; i++) {
                builder.agent("a" + i, new TestAgent(), HalfDie::new);
            }
            MissionOutcome outcome = builder.scheduler(driver.newScheduler()).trace(trace).build()
                    .run(Duration.ofSeconds(20));

            assertEquals(MissionOutcome.Status.FAILED, outcome.status(), outcome::toString);
            List<TraceEvent> events = trace.events();
            List<Integer> waitingOut = trace.events(TraceEvent.WaitingOut.class).stream()
                    .map(TraceEvent.WaitingOut::agent).toList();
            List<TraceEvent.Left> deaths = left(trace, LeaveCause.FAILED);
            List<TraceEvent.Left> ends = left(trace, LeaveCause.END);
            assertEquals(List.of(0, 2, 4, 6), waitingOut.stream().sorted().toList(), events::toString);
            assertEquals(List.of(1, 3, 5), deaths.stream().map(TraceEvent.Left::agent).sorted().toList(), events::toString);
            assertEquals(waitingOut, ends.stream().map(TraceEvent.Left::agent).toList(), events::toString);
            // Every waiting-out member left after the last death, one after the other.
            int firstEnd = events.indexOf(ends.get(0));
            assertTrue(firstEnd > events.indexOf(deaths.get(deaths.size() - 1)), events::toString);
            assertEquals(ends, events.subList(firstEnd, firstEnd + ends.size()), events::toString);
        }
    }

    private static List<TraceEvent.Left> left(MemoryTrace trace, LeaveCause cause) {
        return trace.events(TraceEvent.Left.class).stream().filter(left -> left.cause() == cause).toList();
    }
}
