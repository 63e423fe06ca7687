package masl.runtime.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class JsonLinesTraceTest {

    @Test
    void writesOneJsonObjectPerEvent() {
        StringWriter out = new StringWriter();
        JsonLinesTrace trace = new JsonLinesTrace(out);
        trace.record(new TraceEvent.Entered(1, 0, "main", null));
        trace.record(new TraceEvent.WaitingIn(2, 1, "turn", null));
        trace.record(new TraceEvent.Released(3, 1, "turn", 4, null));
        trace.record(new TraceEvent.WaitingOut(4, 1, "turn", null));
        trace.record(new TraceEvent.Left(5, 1, "turn", LeaveCause.REELECT, null));
        trace.record(new TraceEvent.BarrierTripped(6, "main", 3));
        trace.record(new TraceEvent.WaveStarted(7, "a\"b\\c\n", 1));
        trace.record(new TraceEvent.WaveEnded(8, "turn", 2));
        assertEquals(String.join("\n",
                "{\"nanos\":1,\"event\":\"entered\",\"agent\":0,\"block\":\"main\"}",
                "{\"nanos\":2,\"event\":\"waiting-in\",\"agent\":1,\"block\":\"turn\"}",
                "{\"nanos\":3,\"event\":\"released\",\"agent\":1,\"block\":\"turn\",\"wave\":4}",
                "{\"nanos\":4,\"event\":\"waiting-out\",\"agent\":1,\"block\":\"turn\"}",
                "{\"nanos\":5,\"event\":\"left\",\"agent\":1,\"block\":\"turn\",\"cause\":\"reelect\"}",
                "{\"nanos\":6,\"event\":\"barrier-tripped\",\"domain\":\"main\",\"agents\":3}",
                "{\"nanos\":7,\"event\":\"wave-started\",\"block\":\"a\\\"b\\\\c\\n\",\"wave\":1}",
                "{\"nanos\":8,\"event\":\"wave-ended\",\"block\":\"turn\",\"wave\":2}") + "\n", out.toString());
    }

    @Test
    void startsWithTheAgentsMaslNamesByProxyId() {
        StringWriter out = new StringWriter();
        new JsonLinesTrace(out).record(new TraceEvent.MissionStarted(0, java.util.List.of("leader", "w\"1")));
        assertEquals("{\"nanos\":0,\"event\":\"mission-started\",\"agents\":[\"leader\",\"w\\\"1\"]}\n", out.toString());
    }

    @Test
    void writesEventsWithTheMaslEventsNameUnderName() {
        StringWriter out = new StringWriter();
        JsonLinesTrace trace = new JsonLinesTrace(out);
        trace.record(new TraceEvent.EventEmitted(1, 0, "go", "main", "now \"quoted\"", 4, null));
        trace.record(new TraceEvent.EventEmitted(2, 3, "uncaught_exception", null, "java.lang.NullPointerException", 1, null));
        trace.record(new TraceEvent.EventReacted(3, 1, "go", "main", false, null));
        trace.record(new TraceEvent.EventReacted(4, 2, "go", "work", true, null));
        trace.record(new TraceEvent.EventDropped(5, 0, "go", null));
        assertEquals(String.join("\n",
                "{\"nanos\":1,\"event\":\"event-emitted\",\"agent\":0,\"name\":\"go\",\"block\":\"main\","
                        + "\"message\":\"now \\\"quoted\\\"\",\"receivers\":4}",
                "{\"nanos\":2,\"event\":\"event-emitted\",\"agent\":3,\"name\":\"uncaught_exception\","
                        + "\"block\":null,\"message\":\"java.lang.NullPointerException\",\"receivers\":1}",
                "{\"nanos\":3,\"event\":\"event-reacted\",\"agent\":1,\"name\":\"go\",\"block\":\"main\","
                        + "\"reaction\":\"go\"}",
                "{\"nanos\":4,\"event\":\"event-reacted\",\"agent\":2,\"name\":\"go\",\"block\":\"work\","
                        + "\"reaction\":\"default\"}",
                "{\"nanos\":5,\"event\":\"event-dropped\",\"agent\":0,\"name\":\"go\"}") + "\n", out.toString());
    }

    @Test
    void writesInvocationsAndCountermeasuresWithThePrimitiveUnderMember() {
        StringWriter out = new StringWriter();
        JsonLinesTrace trace = new JsonLinesTrace(out);
        trace.record(new TraceEvent.InvocationMade(1, 0, 1, "getProxyID", null));
        trace.record(new TraceEvent.InvocationServed(2, 1, 0, "getProxyID", null));
        trace.record(new TraceEvent.InvocationDenied(3, 1, -1, "log", "nothing", null));
        trace.record(new TraceEvent.CountermeasureFired(4, 2, 2, "stopGripper", "grip", null));
        assertEquals(String.join("\n",
                "{\"nanos\":1,\"event\":\"invocation-made\",\"requester\":0,\"callee\":1,"
                        + "\"member\":\"getProxyID\"}",
                "{\"nanos\":2,\"event\":\"invocation-served\",\"requester\":0,\"callee\":1,"
                        + "\"member\":\"getProxyID\"}",
                "{\"nanos\":3,\"event\":\"invocation-denied\",\"requester\":-1,\"callee\":1,\"member\":\"log\","
                        + "\"state\":\"nothing\"}",
                "{\"nanos\":4,\"event\":\"countermeasure-fired\",\"agent\":2,\"callee\":2,\"member\":\"stopGripper\","
                        + "\"block\":\"grip\"}") + "\n", out.toString());
    }

    @Test
    void endsAnAgentsRecordWithItsMaslLineAndSource() {
        StringWriter out = new StringWriter();
        JsonLinesTrace trace = new JsonLinesTrace(out);
        trace.record(new TraceEvent.WaitingIn(1, 2, "turn", "e6.masl:14: synchronous entry turn (\"x\")"));
        trace.record(new TraceEvent.AgentFailed(2, 1, "java.lang.ArithmeticException: / by zero", "e.masl:7: x = 1 / y;"));
        trace.record(new TraceEvent.EventDropped(3, 0, "go", "no position"));
        assertEquals(String.join("\n",
                "{\"nanos\":1,\"event\":\"waiting-in\",\"agent\":2,\"block\":\"turn\",\"line\":14,"
                        + "\"source\":\"e6.masl:14: synchronous entry turn (\\\"x\\\")\"}",
                "{\"nanos\":2,\"event\":\"agent-failed\",\"agent\":1,\"cause\":\"java.lang.ArithmeticException: / by zero\","
                        + "\"line\":7,\"source\":\"e.masl:7: x = 1 / y;\"}",
                "{\"nanos\":3,\"event\":\"event-dropped\",\"agent\":0,\"name\":\"go\",\"source\":\"no position\"}") + "\n",
                out.toString());
    }

    @Test
    void aTraceAtItsLimitEndsWithTheRecordSayingItWasCutAndStaysWithinIt() {
        StringWriter out = new StringWriter();
        JsonLinesTrace trace = new JsonLinesTrace(out, 1024);
        for (int i = 0; i < 100; i++) {
            trace.record(new TraceEvent.Entered(i, 0, "tick", "t.masl:5: asynchronous entry tick (true)"));
        }
        trace.record(new TraceEvent.MissionEnded(100, "completed", null));

        String text = out.toString();
        List<String> lines = text.lines().toList();
        assertTrue(text.getBytes(StandardCharsets.UTF_8).length <= 1024, text);
        assertTrue(lines.size() > 2, text);
        assertTrue(lines.get(lines.size() - 1).matches("\\{\"nanos\":\\d+,\"event\":\"trace-cut\",\"limit\":1024}"), text);
        assertTrue(lines.subList(0, lines.size() - 1).stream().allMatch(line -> line.contains("\"entered\"")), text);
        assertTrue(trace.wasCut());
    }

    @Test
    void aMissionEndedThatFitsTheLimitIsNoCut() {
        StringWriter out = new StringWriter();
        JsonLinesTrace trace = new JsonLinesTrace(out, 1024);
        String many = "x".repeat(1024 - 100 - "{\"nanos\":1,\"event\":\"wave-started\",\"block\":\"\",\"wave\":1}\n".length());
        trace.record(new TraceEvent.WaveStarted(1, many, 1));
        trace.record(new TraceEvent.MissionEnded(2, "completed", null));

        assertFalse(trace.wasCut(), out.toString());
        assertTrue(out.toString().endsWith("{\"nanos\":2,\"event\":\"mission-ended\",\"status\":\"completed\"}\n"));
    }

    @Test
    void aWriteThatFailsLosesTheTraceOnceWithoutFailingTheCaller() {
        IOException full = new IOException("No space left on device");
        List<IOException> told = new ArrayList<>();
        JsonLinesTrace trace = new JsonLinesTrace(new Appendable() {
            @Override
            public Appendable append(CharSequence text) throws IOException {
                throw full;
            }

            @Override
            public Appendable append(CharSequence text, int start, int end) throws IOException {
                throw full;
            }

            @Override
            public Appendable append(char c) throws IOException {
                throw full;
            }
        });
        trace.whenFailed(told::add);

        trace.record(new TraceEvent.Entered(1, 0, "main", null));
        trace.record(new TraceEvent.Entered(2, 1, "main", null));

        assertEquals(List.of(full), told, "told once");
        assertEquals(full, trace.failure().orElseThrow());
        List<IOException> late = new ArrayList<>();
        trace.whenFailed(late::add);
        assertEquals(List.of(full), late, "an action given after the failure runs at once");
    }
}
