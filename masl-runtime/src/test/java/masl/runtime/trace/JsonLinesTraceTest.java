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
}
