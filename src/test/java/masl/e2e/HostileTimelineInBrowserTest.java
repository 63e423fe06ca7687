package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * A trace whose strings would steer the HTML tokenizer ({@code <!--<script>} opens a state in which
 * the page's own {@code </script>} no longer ends the data) is drawn like any other in a real
 * browser: the page's script runs and the agents' lanes carry their names as written.
 */
@Tag("slow")
class HostileTimelineInBrowserTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @Test
    void namesAndMessagesThatLookLikeMarkupAreDrawnAsText() throws Exception {
        List<String> names = List.of("a<!--<script>", "b</script><b>\u2028");
        Path out = Files.createDirectories(Path.of("build/timeline"));
        Path trace = out.resolve("hostile.jsonl");
        StringBuilder lines = new StringBuilder();
        for (Map<String, Object> record : List.<Map<String, Object>>of(
                Map.of("nanos", 0, "event", "mission-started", "agents", names),
                Map.of("nanos", 10, "event", "entered", "agent", 0, "block", "main"),
                Map.of("nanos", 10, "event", "entered", "agent", 1, "block", "main"),
                Map.of("nanos", 20, "event", "event-emitted", "agent", 0, "name", "alarm", "message", "<!--<script>"),
                Map.of("nanos", 30, "event", "left", "agent", 0, "block", "main", "cause", "end"),
                Map.of("nanos", 30, "event", "left", "agent", 1, "block", "main", "cause", "end"),
                Map.of("nanos", 40, "event", "mission-ended", "status", "completed"))) {
            lines.append(JSON.writeValueAsString(record)).append('\n');
        }
        Files.writeString(trace, lines);
        Path page = out.resolve("hostile.html");
        MaslCommand timeline = MaslCommand.run("timeline", trace.toString(), "-o", page.toString());
        assertEquals(0, timeline.status(), timeline::toString);

        try (ChromiumPage browser = ChromiumPage.open(page, 1000, 400)) {
            assertEquals(names, List.of(JSON.readValue(browser.evaluate(
                    "JSON.stringify([...document.querySelectorAll('#chart text.agent')].map(t => [...t.childNodes]"
                    + ".filter(n => n.nodeType === Node.TEXT_NODE).map(n => n.textContent).join('')))").asText(),
                    String[].class)));
        }
    }
}
