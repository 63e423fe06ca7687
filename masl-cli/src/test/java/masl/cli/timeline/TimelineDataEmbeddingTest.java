package masl.cli.timeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.StringReader;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The page embeds the trace's strings (agent names, event messages, causes of failure) as JSON in a
 * script element. Whatever those strings hold, the HTML tokenizer must leave the script element
 * where the page put it: strings are drawn at random from the pieces that steer the tokenizer
 * ({@code <!--}, {@code <script>}, {@code </script>}, quotes, backslashes, line separators), and
 * each page is checked to keep no {@code <} in its data and to give back exactly those strings.
 */
class TimelineDataEmbeddingTest {

    private static final String[] PIECES = {
        "<", "!", "-", "--", "/", "script", "SCRIPT", "ScRiPt", ">", "\"", "'", "`", "\\", "\\u003c", "&", "&lt;",
        "\u2028", "\u2029", "\u0085", "\n", "\r", "\t", " ", "\u0000", "\u001f", "x", "\u00e9", "\ud83d\ude00", "\ufeff",
        "<!--", "-->", "</", "<script>", "</script>", "<!--<script>", "]]>", "<![CDATA[", "{", "}", "[", "]",
    };
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String DATA_START = "<script type=\"application/json\" id=\"timeline-data\">";

    @Test
    void aCommentOpenerBeforeAScriptTagStaysData() throws Exception {
        String hostile = "<!--<script>";
        JsonNode data = embeddedData(pageOf(List.of(hostile, "b"), hostile, hostile));

        assertEquals(hostile, data.get("agents").get(0).get("name").asText());
    }

    @Test
    void noGeneratedStringChangesHowThePageIsParsed() throws Exception {
        Random random = new Random(20_260_601L);
        for (int page = 0; page < 300; page++) {
            List<String> names = List.of(hostileString(random), hostileString(random));
            String message = hostileString(random);
            String cause = hostileString(random);

            JsonNode data = embeddedData(pageOf(names, message, cause));

            String seen = "page " + page + " of " + JSON.writeValueAsString(List.of(names, message, cause));
            assertEquals(names.get(0), data.get("agents").get(0).get("name").asText(), seen);
            assertEquals(names.get(1), data.get("agents").get(1).get("name").asText(), seen);
            assertEquals(message, data.get("events").get(0).get("detail").asText(), seen);
            assertEquals(cause, data.get("failures").get(0).get("cause").asText(), seen);
        }
    }

    private static String hostileString(Random random) {
        StringBuilder text = new StringBuilder();
        int pieces = 1 + random.nextInt(12);
        for (int i = 0; i < pieces; i++) {
            text.append(PIECES[random.nextInt(PIECES.length)]);
        }
        return text.toString();
    }

    /** The page of a two-agent trace whose agents are {@code names}, one emitting {@code message}, one failing with {@code cause}. */
    private static String pageOf(List<String> names, String message, String cause) throws Exception {
        List<Map<String, Object>> records = List.of(
                record("nanos", 0, "event", "mission-started", "agents", names),
                record("nanos", 10, "event", "entered", "agent", 0, "block", "main"),
                record("nanos", 20, "event", "event-emitted", "agent", 0, "name", "alarm", "message", message),
                record("nanos", 30, "event", "agent-failed", "agent", 1, "cause", cause),
                record("nanos", 40, "event", "mission-ended", "status", "failed"));
        StringBuilder trace = new StringBuilder();
        for (Map<String, Object> record : records) {
            trace.append(JSON.writeValueAsString(record)).append('\n');
        }
        Timeline timeline = Timeline.of(TraceReader.read("hostile.jsonl", new StringReader(trace.toString())));
        return new TimelineHtml(timeline, "hostile").render();
    }

    /**
     * The data element as an HTML tokenizer reads it: it ends at the first {@code </script}, whatever
     * the case; it must hold no {@code <} (the only character that can change the script data state)
     * and be the whole JSON of the timeline.
     */
    private static JsonNode embeddedData(String page) throws Exception {
        int start = page.indexOf(DATA_START) + DATA_START.length();
        int end = page.toLowerCase(Locale.ROOT).indexOf("</script", start);
        String data = page.substring(start, end);
        assertFalse(data.contains("<"), "a < in the page's data: " + data);
        assertFalse(data.contains("\u2028") || data.contains("\u2029"), "a line separator in the page's data");
        JsonNode parsed = JSON.readTree(data);
        assertTrue(parsed.has("markers"), "the data element holds the whole timeline");
        return parsed;
    }

    private static Map<String, Object> record(Object... pairs) {
        Map<String, Object> fields = new LinkedHashMap<>();
        for (int i = 0; i < pairs.length; i += 2) {
            fields.put((String) pairs[i], pairs[i + 1]);
        }
        return fields;
    }
}
