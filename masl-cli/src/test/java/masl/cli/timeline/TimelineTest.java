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
            {"nanos":4000,"event":"event-emitted","agent":0,"block":"work <&>","name":"alarm"}
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
        assertEquals(List.of(new Timeline.EventMark(4000, 0, "alarm", Timeline.EventKind.EMITTED, null, -1, null)),
                timeline.events());
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
        String page = new TimelineHtml(Timeline.of(read(TRACE.replace("work <&>", "</script><b>x"))), "trace <1>").render();

        assertTrue(page.startsWith("<!DOCTYPE html>"));
        assertTrue(page.contains("<title>trace &lt;1&gt;</title>"));
        assertTrue(page.contains("\\u003C/script\\u003E\\u003Cb\\u003Ex"), "a name in the data cannot end its script");
        assertEquals(2, page.split("</script>", -1).length - 1, "the data's and the drawing's scripts only");
        assertFalse(page.contains("<script src"), "no external script");
        assertFalse(page.contains("<link"), "no external style");
        assertFalse(page.replace("http://www.w3.org/2000/svg", "").contains("http"), "nothing fetched");
    }

    private static final String E5_LIKE = """
            {"nanos":0,"event":"mission-started","agents":["a","b"]}
            {"nanos":10,"event":"entered","agent":0,"block":"main"}
            {"nanos":10,"event":"entered","agent":1,"block":"main"}
            {"nanos":20,"event":"invocation-made","requester":0,"callee":1,"member":"getProxyID","line":8,"source":"e5.masl:8: seen = b.getProxyID();"}
            {"nanos":30,"event":"invocation-denied","requester":0,"callee":1,"member":"getProxyID","state":"nothing"}
            {"nanos":40,"event":"event-emitted","agent":0,"name":"timeout","block":null,"message":"getProxyID","receivers":1}
            {"nanos":50,"event":"event-reacted","agent":0,"name":"timeout","block":"main","reaction":"timeout"}
            {"nanos":60,"event":"entered","agent":1,"block":"tick"}
            {"nanos":60,"event":"left","agent":1,"block":"tick","cause":"end"}
            {"nanos":70,"event":"left","agent":1,"block":"main","cause":"failed"}
            {"nanos":70,"event":"agent-failed","agent":1,"cause":"java.lang.ArithmeticException: / by zero"}
            {"nanos":80,"event":"mission-ended","status":"failed"}
            """;

    @Test
    void agentsAreNamedInvocationsPairedAndSystemEventsNamedNoBlock() throws Exception {
        Timeline timeline = Timeline.of(read(E5_LIKE));

        assertEquals(java.util.Map.of(0, "a", 1, "b"), timeline.agents());
        assertEquals(List.of("main", "tick"), List.copyOf(timeline.blocks()), "the system event timeout is no block");
        assertEquals(List.of(new Timeline.Invocation(20, 30, 0, 1, "getProxyID", Timeline.Outcome.DENIED, "nothing",
                "e5.masl:8: seen = b.getProxyID();")), timeline.invocations());
        assertEquals(0, timeline.events().get(1).emission(), "the reaction answers the emission");
        assertEquals(List.of(new Timeline.Failure(70, 1, "java.lang.ArithmeticException: / by zero", null)), timeline.failures());
        assertTrue(timeline.lanes().get(1).contains(new Span(60, 60, "tick", State.RUNNING)),
                "a block entered and left at one time is kept: " + timeline.lanes().get(1));
        assertEquals(new Timeline.Marker(60, 1, "first-entry", "enters tick", null), timeline.markers().get(0));
        assertEquals(new Timeline.Marker(70, 1, "left", "left main (failed)", null), timeline.markers().get(1));
        assertEquals("failed", timeline.status());
        String page = new TimelineHtml(timeline, "e5").render();
        assertFalse(page.contains("\"null\""), "no block named null");
    }

    @Test
    void aTraceCutAtItsLimitIsReadAndSaysSo() throws Exception {
        Timeline timeline = Timeline.of(read("""
                {"nanos":0,"event":"mission-started","agents":["a"]}
                {"nanos":10,"event":"entered","agent":0,"block":"main"}
                {"nanos":20,"event":"trace-cut","limit":1024}
                """));

        assertEquals("trace cut at its limit of 1024 bytes", timeline.status());
        assertTrue(new TimelineHtml(timeline, "cut").render().contains("trace cut at its limit of 1024 bytes"));
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
