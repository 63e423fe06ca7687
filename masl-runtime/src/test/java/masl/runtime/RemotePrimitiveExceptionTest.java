package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
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

    /** {@code v = .drain(1);}, failed in another JVM: {@code v} takes the default value 0. */
    private static final MaslProgram FAILING = MaslProgram.of("remote.masl", 2, """
            asynchronous entry main (true) {
              local int v = 7;
              v = .drain(1);
              .logln("v=" + v);
            }
            """);

    @Test
    void aRemoteFailureIsAnUncaughtExceptionNamedAfterTheRemoteClass() {
        MemoryTrace trace = new MemoryTrace();
        String journal = FAILING.run(Driver.THREADS.newScheduler(), trace, () -> new TestAgent() {
            @Override
            public int drain(int amount) {
                throw new RemotePrimitiveException("java.lang.ArithmeticException", "/ by zero");
            }
        }).journal();
        assertEquals("v=0\nv=0\n", journal);
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
