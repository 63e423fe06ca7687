package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** A trace a stopped or failed {@code masl run} left: whole JSON lines, nothing cut mid-record. */
final class CompleteTrace {

    private CompleteTrace() {
    }

    /** Asserts that every line of {@code trace} is a whole JSON record, and returns the last. */
    static JsonNode lastRecord(Path trace) throws IOException {
        String text = Files.readString(trace);
        assertTrue(text.endsWith("}\n"), () -> "cut mid-record: " + text.substring(Math.max(0, text.length() - 200)));
        List<String> lines = text.lines().toList();
        ObjectMapper json = new ObjectMapper();
        for (String line : lines) {
            json.readTree(line);
        }
        return json.readTree(lines.get(lines.size() - 1));
    }
}
