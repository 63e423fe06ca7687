package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import masl.runtime.MissionOutcome;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * An agent whose program fails ({@code 1 / z} with {@code z} zero) is reported at the MASL line of the
 * statement that failed, in the trace's {@code agent-failed} and in the mission's failure, whatever
 * the statement placed first after its block's declarations, which once shared their case.
 */
@Timeout(60)
class FailureLineTest {

    /** Line 8 is the statement under test, right after the declarations of lines 4 to 7. */
    private static final String HEAD = """
            import Default.xml;
            Default a, b = newAgent(Default);
            asynchronous entry main (true) {
                local int z = 0;
                local int y = 1;
                local event e;
                SLabel l;
            """;

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            assignment                         | 8  | y = 1 / z;
            self invocation                    | 8  | .logln(1 / z);
            external invocation                | 8  | b.log(1 / z);
            label launch                       | 8  | l.b.logln(1 / z);
            emit with a message                | 8  | emitWithMessage(e, 1 / z);
            setAcceptState                     | 8  | setAcceptState("s" + 1 / z);
            wait                               | 8  | wait("s" + 1 / z);
            if's condition                     | 8  | if (1 / z > 0) {\\n.nop();\\n}
            if's first statement               | 9  | if (z == 0) {\\ny = 1 / z;\\n}
            while's condition                  | 8  | while (1 / z > 0) {\\n.nop();\\n}
            while's first statement            | 9  | while (z == 0) {\\ny = 1 / z;\\n}
            for's initialisation               | 8  | for (y = 1 / z; y < 3; y++) {\\n.nop();\\n}
            do's first statement               | 9  | do {\\ny = 1 / z;\\n} loop
            block's first statement            | 9  | {\\ny = 1 / z;\\n}
            nested entry's test                | 8  | scalar entry inner (1 / z > 0) {\\n.nop();\\n}
            nested entry's first statement     | 10 | asynchronous entry inner (true) {\\nlocal int q = 0;\\ny = 1 / z;\\n}
            statement after a break's if       | 9  | if (z > 0) break;\\ny = 1 / z;
            """)
    void aFailureIsReportedAtTheLineOfItsStatement(String kind, int line, String statement) throws InterruptedException {
        String program = HEAD + statement.replace("\\n", "\n") + "\n.logln(\"not reached\");\n}\n";
        MemoryTrace trace = new MemoryTrace();
        MissionOutcome outcome = Programs.load(program).newMission().scheduler(new SeededScheduler(1)).trace(trace)
                .build().run(Duration.ofSeconds(30));

        assertEquals(MissionOutcome.Status.FAILED, outcome.status(), outcome::toString);
        List<TraceEvent.AgentFailed> failures = trace.events(TraceEvent.AgentFailed.class);
        assertFalse(failures.isEmpty(), trace.events()::toString);
        for (TraceEvent.AgentFailed failure : failures) {
            assertEquals("java.lang.ArithmeticException: / by zero", failure.cause());
            assertTrue(failure.source().startsWith("test.masl:" + line + ": "), failure::toString);
        }
        String failed = outcome.failure().orElseThrow().getMessage();
        assertTrue(failed.contains("(test.masl:" + line + ": "), failed);
    }
}
