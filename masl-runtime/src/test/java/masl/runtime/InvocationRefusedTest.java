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
 * A primitive whose body refused to run it (a body in another JADE container answering
 * {@code REFUSE}) throws {@link InvocationRefusedException}: the caller perceives {@code timeout}
 * with the primitive's name, as for a denial, not {@code uncaught_exception}, and gets the default value.
 */
@Timeout(30)
class InvocationRefusedTest {

    /** {@code v = .drain(1);}, refused: {@code v} takes the default value 0. */
    private static final MaslProgram FAILING = MaslProgram.of("refused.masl", 2, """
            asynchronous entry main (true) {
              local int v = 7;
              v = .drain(1);
              .logln("v=" + v);
            }
            """);

    @Test
    void aRefusedPrimitiveIsATimeoutWithTheDefaultValue() {
        MemoryTrace trace = new MemoryTrace();
        String journal = FAILING.run(Driver.THREADS.newScheduler(), trace, () -> new TestAgent() {
            @Override
            public int drain(int amount) {
                throw new InvocationRefusedException("drain", "its body no longer serves");
            }
        }).journal();
        assertEquals("v=0\nv=0\n", journal);
        assertEquals(List.of("timeout drain", "timeout drain"), trace.events(TraceEvent.EventEmitted.class).stream()
                .map(event -> event.event() + " " + event.message()).toList());
    }
}
