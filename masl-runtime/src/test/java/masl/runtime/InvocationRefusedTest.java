package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A primitive whose body refused to run it (a body in another JADE container answering
 * {@code REFUSE}) throws {@link InvocationRefusedException}: the caller perceives {@code timeout}
 * with the primitive's name, as for a denial, not {@code uncaught_exception}, and gets the default value.
 */
@Timeout(30)
class InvocationRefusedTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);

    /** {@code asynchronous entry main (true) { v = .add(); }} with an {@code add} that is refused. */
    static final class Refused extends CompactProgram {
        private final Queue<Integer> results;

        Refused(TestAgent self, Queue<Integer> results) {
            super(self);
            this.results = results;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0:
                        pc = 1;
                        if (ctx.enter(MAIN, true) == Arrival.WAITING) return;
                    case 1:
                        results.add(ctx.invokeSelf("add", 7, () -> {
                            throw new InvocationRefusedException("add", "its body no longer serves");
                        }));
                        pc = 2;
                        if (!ctx.stepBoundary()) return;
                    case 2:
                        pc = 3;
                        if (!ctx.leave(MAIN)) return;
                    case 3:
                        pc = 4;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                    case 4:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @Test
    void aRefusedPrimitiveIsATimeoutWithTheDefaultValue() {
        Queue<Integer> results = new ConcurrentLinkedQueue<>();
        MemoryTrace trace = new MemoryTrace();
        Missions.run(Driver.THREADS, MAIN, 2, self -> new Refused(self, results), trace);
        assertEquals(List.of(7, 7), List.copyOf(results));
        assertEquals(List.of("timeout add", "timeout add"), trace.events(TraceEvent.EventEmitted.class).stream()
                .map(event -> event.event() + " " + event.message()).toList());
    }
}
