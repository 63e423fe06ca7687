package masl.runtime.trace;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.StringWriter;
import org.junit.jupiter.api.Test;

class JsonLinesTraceTest {

    @Test
    void writesOneJsonObjectPerEvent() {
        StringWriter out = new StringWriter();
        JsonLinesTrace trace = new JsonLinesTrace(out);
        trace.record(new TraceEvent.Entered(1, 0, "main"));
        trace.record(new TraceEvent.WaitingIn(2, 1, "turn"));
        trace.record(new TraceEvent.Released(3, 1, "turn", 4));
        trace.record(new TraceEvent.WaitingOut(4, 1, "turn"));
        trace.record(new TraceEvent.Left(5, 1, "turn", LeaveCause.REELECT));
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
    void writesEventsWithTheMaslEventsNameUnderName() {
        StringWriter out = new StringWriter();
        JsonLinesTrace trace = new JsonLinesTrace(out);
        trace.record(new TraceEvent.EventEmitted(1, 0, "go", "main", "now \"quoted\"", 4));
        trace.record(new TraceEvent.EventEmitted(2, 3, "uncaught_exception", null, "java.lang.NullPointerException", 1));
        trace.record(new TraceEvent.EventReacted(3, 1, "go", "main", false));
        trace.record(new TraceEvent.EventReacted(4, 2, "go", "work", true));
        trace.record(new TraceEvent.EventDropped(5, 0, "go"));
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
        trace.record(new TraceEvent.InvocationMade(1, 0, 1, "getProxyID"));
        trace.record(new TraceEvent.InvocationServed(2, 1, 0, "getProxyID"));
        trace.record(new TraceEvent.InvocationDenied(3, 1, -1, "log", "nothing"));
        trace.record(new TraceEvent.CountermeasureFired(4, 2, 2, "stopGripper", "grip"));
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
}
