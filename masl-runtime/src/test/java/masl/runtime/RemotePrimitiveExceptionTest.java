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
 * A primitive that failed in another JVM throws {@link RemotePrimitiveException}: the caller perceives
 * {@code uncaught_exception} named after the remote exception's class, as if it had been thrown here,
 * and gets the default value.
 */
@Timeout(30)
class RemotePrimitiveExceptionTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);

    /** {@code asynchronous entry main (true) { v = .divide(); }} with a {@code divide} that failed remotely. */
    static final class FailsRemotely extends CompactProgram {
        private final Queue<Integer> results;

        FailsRemotely(TestAgent self, Queue<Integer> results) {
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
                        results.add(ctx.invokeSelf("divide", -1, () -> {
                            throw new RemotePrimitiveException("java.lang.ArithmeticException", "/ by zero");
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
    void aRemoteFailureIsAnUncaughtExceptionNamedAfterTheRemoteClass() {
        Queue<Integer> results = new ConcurrentLinkedQueue<>();
        MemoryTrace trace = new MemoryTrace();
        Missions.run(Driver.THREADS, MAIN, 2, self -> new FailsRemotely(self, results), trace);
        assertEquals(List.of(-1, -1), List.copyOf(results));
        assertEquals(List.of("uncaught_exception java.lang.ArithmeticException",
                "uncaught_exception java.lang.ArithmeticException"),
                trace.events(TraceEvent.EventEmitted.class).stream().map(e -> e.event() + " " + e.message()).toList());
    }

    @Test
    void itReadsAsTheRemoteExceptionInReports() {
        assertEquals("java.lang.ArithmeticException: / by zero",
                new RemotePrimitiveException("java.lang.ArithmeticException", "/ by zero").toString());
        assertEquals("java.lang.IllegalStateException",
                new RemotePrimitiveException("java.lang.IllegalStateException", null).toString());
    }
}
