package masl.cli.timeline;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads a trace written by {@code masl run --trace FILE}: one JSON object per line, each with at
 * least {@code nanos} (a number) and {@code event} (a string). A field whose value is JSON
 * {@code null} (the block of a system event) is absent, not the text {@code "null"}; arrays (the
 * agents' names of {@code mission-started}) are lists. Blank lines are skipped; anything else is
 * an error naming the file, line and column.
 */
public final class TraceReader {

    private static final ObjectMapper JSON = new ObjectMapper();

    private TraceReader() {
    }

    public static List<TraceRecord> read(String fileName, Reader text) throws IOException, TraceFormatException {
        List<TraceRecord> records = new ArrayList<>();
        BufferedReader lines = new BufferedReader(text);
        int number = 0;
        for (String line = lines.readLine(); line != null; line = lines.readLine()) {
            number++;
            if (!line.isBlank()) {
                records.add(record(fileName, number, line));
            }
        }
        return records;
    }

    private static TraceRecord record(String file, int line, String text) throws TraceFormatException {
        JsonNode node;
        try {
            node = JSON.readTree(text);
        } catch (JsonProcessingException malformed) {
            JsonLocation at = malformed.getLocation();
            throw new TraceFormatException(file, line, at == null ? 1 : Math.max(1, at.getColumnNr()), malformed.getOriginalMessage());
        }
        if (node == null || !node.isObject()) {
            throw new TraceFormatException(file, line, 1, "expected a JSON object");
        }
        JsonNode nanos = node.get("nanos");
        JsonNode event = node.get("event");
        if (nanos == null || !nanos.canConvertToLong()) {
            throw new TraceFormatException(file, line, 1, "expected a number \"nanos\"");
        }
        if (event == null || !event.isTextual()) {
            throw new TraceFormatException(file, line, 1, "expected a string \"event\"");
        }
        JsonNode agent = node.get("agent");
        if (agent != null && !agent.canConvertToInt()) {
            throw new TraceFormatException(file, line, 1, "\"agent\" must be an agent's number");
        }
        Map<String, String> fields = new LinkedHashMap<>();
        Map<String, List<String>> lists = new LinkedHashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> all = node.fields(); all.hasNext(); ) {
            Map.Entry<String, JsonNode> field = all.next();
            JsonNode value = field.getValue();
            if (value.isArray()) {
                List<String> items = new ArrayList<>();
                value.forEach(item -> items.add(item.isTextual() ? item.asText() : item.toString()));
                lists.put(field.getKey(), items);
            } else if (!value.isNull()) {
                fields.put(field.getKey(), value.isTextual() ? value.asText() : value.toString());
            }
        }
        return new TraceRecord(line, nanos.asLong(), event.asText(), agent == null ? TraceRecord.NO_AGENT : agent.asInt(),
                fields.get("block"), fields, lists);
    }
}
