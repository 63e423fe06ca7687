package masl.jade.acl;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.Iterator;

/**
 * The content of an {@code INFORM} (conversation {@code masl-event}) by which a FIPA agent raises a
 * shared event of the mission: {@code {"event": "go", "message": "now"}}, {@code message} optional
 * ({@code ""}), no other field.
 *
 * @param event   the shared event's name
 * @param message its message, {@code ""} if none
 */
public record EventContent(String event, String message) {

    private static final ObjectMapper MAPPER = new ObjectMapper();

    /** @throws ContentException if the content is not such an object */
    public static EventContent parse(String content) throws ContentException {
        JsonNode node;
        try {
            node = MAPPER.readTree(content == null ? "" : content);
        } catch (JsonProcessingException malformed) {
            JsonLocation at = malformed.getLocation();
            throw new ContentException("malformed JSON: " + malformed.getOriginalMessage().lines().findFirst().orElse(""),
                    at == null ? 1 : Math.max(1, at.getLineNr()), at == null ? 1 : Math.max(1, at.getColumnNr()));
        }
        if (node == null || !node.isObject()) {
            throw new ContentException("expected an object {\"event\": name, \"message\": text}", 1, 1);
        }
        for (Iterator<String> fields = node.fieldNames(); fields.hasNext(); ) {
            String field = fields.next();
            if (!field.equals("event") && !field.equals(JsonContent.MESSAGE)) {
                throw new ContentException("unknown field \"" + field + "\": an event has \"event\" and \"message\"",
                        1, 1);
            }
        }
        JsonNode event = node.get("event");
        if (event == null || !event.isTextual() || event.asText().isEmpty()) {
            throw new ContentException("\"event\" must name a shared event", 1, 1);
        }
        JsonNode message = node.get(JsonContent.MESSAGE);
        if (message != null && !message.isTextual()) {
            throw new ContentException("\"message\" must be a string", 1, 1);
        }
        return new EventContent(event.asText(), message == null ? "" : message.asText());
    }
}
