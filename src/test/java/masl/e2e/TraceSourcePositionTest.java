package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code masl run --trace}: every record of an agent at a statement carries that statement's MASL
 * line and source, shown on example E4 (events), seeded.
 */
@Timeout(120)
class TraceSourcePositionTest {

    private static final Set<String> MISSION_WIDE = Set.of("mission-started", "wave-started", "wave-ended", "barrier-tripped", "mission-ended");

    @TempDir
    Path folder;

    @Test
    void everyAgentRecordOfE4NamesItsMaslStatement() throws IOException {
        Path trace = folder.resolve("e4.jsonl");
        MaslCommand run = MaslCommand.run("run", "src/test/resources/examples/e4_events.masl", "--seed", "1",
                "--trace", trace.toString());
        assertEquals(0, run.status(), run::toString);
        List<JsonNode> records = new ArrayList<>();
        for (String line : Files.readAllLines(trace)) {
            records.add(new ObjectMapper().readTree(line));
        }
        for (JsonNode record : records) {
            if (!MISSION_WIDE.contains(record.get("event").asText())) {
                assertTrue(record.get("source").asText().startsWith("e4_events.masl:" + record.get("line").asInt() + ": "),
                        record::toString);
            }
        }
        // main has one wave (§4): every agent is held at its arrival until all have tested it
        assertEquals(List.of("4: asynchronous entry main (true)"), sources(records, "waiting-in", "main"));
        assertEquals(List.of("4: asynchronous entry main (true)"), sources(records, "released", "main"));
        assertEquals(List.of("12: asynchronous entry work (.getProxyID() != 0)"), sources(records, "entered", "work"));
        assertEquals(List.of("10: emitWithMessage(go, \"now\");"), sources(records, "event-emitted", "main"));
        // The leader reacts at the boundary of its emit; the workers are woken in their busy-wait.
        assertEquals(List.of("10: emitWithMessage(go, \"now\");", "14: while (!started)"), sources(records, "event-reacted", "main"));
        assertEquals(List.of("16: end of work"), sources(records, "left", "work"));
        assertEquals(List.of("22: end of main"), sources(records, "left", "main"));
    }

    /** The distinct sources of the records of one kind and block, in first-seen order, without the file name. */
    private static List<String> sources(List<JsonNode> records, String event, String block) {
        return records.stream()
                .filter(r -> r.get("event").asText().equals(event) && block.equals(r.path("block").asText()))
                .map(r -> r.get("source").asText().substring("e4_events.masl:".length()))
                .distinct()
                .toList();
    }
}
