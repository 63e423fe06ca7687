package masl.cli.timeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.util.List;
import masl.cli.timeline.Timeline.Span;
import masl.cli.timeline.Timeline.State;
import org.junit.jupiter.api.Test;

class TimelineTest {

    private static final String TRACE = """
            {"nanos":1000,"event":"waiting-in","agent":0,"block":"main"}
            {"nanos":1000,"event":"waiting-in","agent":1,"block":"main"}
            {"nanos":2000,"event":"wave-started","block":"main","wave":1}
            {"nanos":2000,"event":"released","agent":0,"block":"main","wave":1}
            {"nanos":2000,"event":"released","agent":1,"block":"main","wave":1}
            {"nanos":3000,"event":"entered","agent":0,"block":"work <&>"}
            {"nanos":4000,"event":"event-emitted","agent":0,"block":"work <&>","event-name":"alarm"}
            {"nanos":5000,"event":"left","agent":0,"block":"work <&>","cause":"end"}
            {"nanos":6000,"event":"barrier-tripped","domain":"main","agents":2}

            {"nanos":7000,"event":"waiting-out","agent":0,"block":"main"}
            {"nanos":8000,"event":"left","agent":0,"block":"main","cause":"end"}
            {"nanos":8000,"event":"left","agent":1,"block":"main","cause":"end"}
            {"nanos":8000,"event":"wave-ended","block":"main","wave":1}
            """;

    @Test
    void eachAgentsLaneFollowsItsInnermostBlockAndState() throws Exception {
        Timeline timeline = Timeline.of(read(TRACE));

        assertEquals(List.of(
                new Span(1000, 2000, "main", State.WAITING_IN),
                new Span(2000, 3000, "main", State.RUNNING),
                new Span(3000, 5000, "work <&>", State.RUNNING),
                new Span(5000, 7000, "main", State.RUNNING),
                new Span(7000, 8000, "main", State.WAITING_OUT)), timeline.lanes().get(0));
        assertEquals(List.of(
                new Span(1000, 2000, "main", State.WAITING_IN),
                new Span(2000, 8000, "main", State.RUNNING)), timeline.lanes().get(1));
        assertEquals(List.of(new Timeline.Trip(6000, "main", "2")), timeline.trips());
        assertEquals(List.of(new Timeline.WaveSpan("main", "1", 2000, 8000)), timeline.waves());
        assertEquals(1, timeline.markers().size());
        assertTrue(timeline.markers().get(0).label().contains("event-name=alarm"));
        assertFalse(timeline.inRecordOrder());
    }

    @Test
    void aTraceOnAVirtualClockIsLaidOutInRecordOrder() throws Exception {
        Timeline timeline = Timeline.of(read(TRACE.replaceAll("\"nanos\":\\d+", "\"nanos\":0")));

        assertTrue(timeline.inRecordOrder());
        assertEquals(new Span(0, 3, "main", State.WAITING_IN), timeline.lanes().get(0).get(0));
    }

    @Test
    void thePageIsSelfContainedAndEscapesNames() throws Exception {
        String page = new TimelineHtml(Timeline.of(read(TRACE)), "trace <1>").render();

        assertTrue(page.startsWith("<!DOCTYPE html>"));
        assertTrue(page.contains("work &lt;&amp;&gt;"));
        assertFalse(page.contains("work <&>"));
        assertFalse(page.contains("<script"), "no script");
        assertFalse(page.contains("<link"), "no external style");
        assertFalse(page.replace("xmlns=\"http://www.w3.org/2000/svg\"", "").contains("http"), "nothing fetched");
    }

    @Test
    void aMalformedLineIsReportedWithFileLineAndColumn() {
        TraceFormatException broken = assertThrows(TraceFormatException.class,
                () -> TraceReader.read("run.jsonl", new StringReader("{\"nanos\":1,\"event\":\"left\"}\n{\"nanos\":2,\"event\" \"x\"}\n")));
        assertTrue(broken.getMessage().startsWith("run.jsonl:2:"), broken.getMessage());

        TraceFormatException noTime = assertThrows(TraceFormatException.class,
                () -> TraceReader.read("run.jsonl", new StringReader("\n\n{\"event\":\"left\"}\n")));
        assertEquals("run.jsonl:3:1: error: expected a number \"nanos\"", noTime.getMessage());

        TraceFormatException notAnObject = assertThrows(TraceFormatException.class,
                () -> TraceReader.read("run.jsonl", new StringReader("[1, 2]\n")));
        assertEquals("run.jsonl:1:1: error: expected a JSON object", notAnObject.getMessage());
    }

    private static List<TraceRecord> read(String trace) throws IOException, TraceFormatException {
        return TraceReader.read("test.jsonl", new StringReader(trace));
    }
}
