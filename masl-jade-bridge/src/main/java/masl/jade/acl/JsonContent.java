package masl.jade.acl;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import masl.runtime.RemotePrimitiveException;

/**
 * The JSON content of invocation messages (components.md, "JADE bridge"), never Java
 * serialisation:
 * <pre>
 * REQUEST          {"primitive": "log", "args": ["hello"]}
 * INFORM           {"result": 42}                       (null for a void primitive)
 * REFUSE           {"reason": "…"}
 * FAILURE          {"exception": "java.lang.ArithmeticException", "message": "/ by zero"}
 * NOT_UNDERSTOOD   {"error": "content:1:12: error: …"}
 * </pre>
 * A request is read strictly: one object, {@code primitive} a string, {@code args} an array (may be
 * left out when there are none), no other field, nothing after the object. Every problem is a
 * {@link ContentException} positioned in the content. Values are written by {@link JsonValues}.
 * Thread-safe.
 */
public final class JsonContent {

    public static final String PRIMITIVE = "primitive";
    public static final String ARGS = "args";
    public static final String RESULT = "result";
    public static final String REASON = "reason";
    public static final String EXCEPTION = "exception";
    public static final String MESSAGE = "message";
    public static final String ERROR = "error";
    /** In a body's answer to the coordinator: the journal text the primitive wrote. */
    public static final String JOURNAL = "journal";

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;
    private static final String NULL_RESULT = "{\"" + RESULT + "\":null}";
    private static final Pattern SOURCE_REFERENCE = Pattern.compile("\\[Source: [^;]*; line: (\\d+), column: (\\d+)]");

    private JsonContent() {
    }

    /** The content of a request invoking {@code primitive} with {@code args} (see {@link JsonValues}). */
    public static String request(String primitive, List<?> args) {
        ObjectNode request = NODES.objectNode();
        request.put(PRIMITIVE, primitive);
        request.set(ARGS, JsonValues.toJson(args));
        return request.toString();
    }

    /**
     * Reads the content of an invocation request.
     *
     * @throws ContentException if it is not JSON or not a request, positioned where it goes wrong
     */
    public static InvocationRequest parseRequest(String content) throws ContentException {
        if (content == null || content.isBlank()) {
            throw new ContentException("empty content: expected {\"" + PRIMITIVE + "\": name, \"" + ARGS
                    + "\": [...]}", 1, 1);
        }
        try (JsonParser parser = MAPPER.createParser(content)) {
            JsonToken first = parser.nextToken();
            JsonLocation start = parser.currentTokenLocation();
            if (first != JsonToken.START_OBJECT) {
                throw at(parser, "expected an object {\"" + PRIMITIVE + "\": name, \"" + ARGS + "\": [...]}");
            }
            String primitive = null;
            JsonLocation primitiveStart = null;
            List<Argument> args = null;
            while (parser.nextToken() == JsonToken.FIELD_NAME) {
                String field = parser.currentName();
                JsonLocation fieldStart = parser.currentTokenLocation();
                parser.nextToken();
                if (PRIMITIVE.equals(field) && primitive == null) {
                    primitiveStart = parser.currentTokenLocation();
                    primitive = primitiveName(parser);
                } else if (ARGS.equals(field) && args == null) {
                    args = arguments(parser);
                } else if (PRIMITIVE.equals(field) || ARGS.equals(field)) {
                    throw at(fieldStart, "duplicate field \"" + field + "\"");
                } else {
                    throw at(fieldStart, "unknown field \"" + field + "\": a request has only \"" + PRIMITIVE
                            + "\" and \"" + ARGS + "\"");
                }
            }
            if (primitive == null) {
                throw at(start, "missing field \"" + PRIMITIVE + "\": the name of the primitive to invoke");
            }
            if (parser.nextToken() != null) {
                throw at(parser, "unexpected content after the request object");
            }
            return new InvocationRequest(primitive, primitiveStart.getLineNr(), primitiveStart.getColumnNr(),
                    args == null ? List.of() : args);
        } catch (JsonProcessingException e) {
            JsonLocation location = e.getLocation();
            throw new ContentException("malformed JSON: " + firstLine(e.getOriginalMessage()),
                    location == null ? 1 : Math.max(1, location.getLineNr()),
                    location == null ? 1 : Math.max(1, location.getColumnNr()));
        } catch (IOException e) {
            throw new ContentException("unreadable content: " + e.getMessage(), 1, 1);
        }
    }

    private static String primitiveName(JsonParser parser) throws IOException, ContentException {
        if (parser.currentToken() != JsonToken.VALUE_STRING || parser.getValueAsString().isEmpty()) {
            throw at(parser, "\"" + PRIMITIVE + "\" must be a primitive's name, a non-empty string");
        }
        return parser.getValueAsString();
    }

    private static List<Argument> arguments(JsonParser parser) throws IOException, ContentException {
        if (parser.currentToken() != JsonToken.START_ARRAY) {
            throw at(parser, "\"" + ARGS + "\" must be an array of the arguments");
        }
        List<Argument> args = new ArrayList<>();
        while (parser.nextToken() != JsonToken.END_ARRAY) {
            JsonLocation location = parser.currentTokenLocation();
            JsonNode value = MAPPER.readTree(parser);
            args.add(new Argument(value, location.getLineNr(), location.getColumnNr()));
        }
        return args;
    }

    /** The content of an {@code INFORM} answering a request: the primitive's result. */
    public static String result(Object value) {
        if (value == null) {
            // A void primitive's answer, the most frequent one: no tree to build and write.
            return NULL_RESULT;
        }
        ObjectNode result = NODES.objectNode();
        result.set(RESULT, JsonValues.toJson(value));
        return result.toString();
    }

    /**
     * The content of a body's {@code INFORM} to the coordinator: the result, and the journal text
     * the primitive wrote, which the coordinator appends to the mission's journal.
     */
    public static String result(Object value, String journal) {
        ObjectNode result = (ObjectNode) readObject(result(value));
        return result.put(JOURNAL, journal).toString();
    }

    /** The content of a body's {@code FAILURE} to the coordinator: the exception and the journal text written before it. */
    public static String failure(Throwable thrown, String journal) {
        return ((ObjectNode) readObject(failure(thrown))).put(JOURNAL, journal).toString();
    }

    /** The journal text of a body's answer; {@code ""} if it has none (or is not JSON). */
    public static String journalOf(String content) {
        JsonNode journal = readObject(content).path(JOURNAL);
        return journal.isTextual() ? journal.textValue() : "";
    }

    private static JsonNode readObject(String content) {
        try {
            JsonNode node = MAPPER.readTree(content == null ? "" : content);
            return node == null ? NODES.objectNode() : node;
        } catch (JsonProcessingException notJson) {
            return NODES.objectNode();
        }
    }

    /** The content of a shared event's {@code INFORM} (conversation {@code masl-event}). */
    public static String event(String event, String block, String emitter, String message) {
        return NODES.objectNode().put("event", event).put("block", block).put("emitter", emitter)
                .put(MESSAGE, message).toString();
    }

    /** The content of a {@code REFUSE}: why the invocation was denied. */
    public static String refusal(String reason) {
        return NODES.objectNode().put(REASON, reason).toString();
    }

    /** The content of a {@code FAILURE}: the exception the primitive threw. */
    public static String failure(Throwable thrown) {
        return NODES.objectNode().put(EXCEPTION, RemotePrimitiveException.classNameOf(thrown))
                .put(MESSAGE, thrown.getMessage()).toString();
    }

    /**
     * What an answer that is not a result says went wrong, in words: the message of a
     * {@code FAILURE} (or its exception's name if it has none), the reason of a {@code REFUSE}, the
     * error of a {@code NOT_UNDERSTOOD}; the content itself if it has none of these.
     */
    public static String failureMessage(String content) {
        JsonNode answer = readObject(content);
        for (String field : List.of(MESSAGE, REASON, ERROR, EXCEPTION)) {
            if (answer.path(field).isTextual()) {
                return answer.path(field).textValue();
            }
        }
        return String.valueOf(content);
    }

    /** The content of a {@code NOT_UNDERSTOOD}: {@link ContentException#describe()}. */
    public static String notUnderstood(ContentException problem) {
        return NODES.objectNode().put(ERROR, problem.describe()).toString();
    }

    /**
     * Reads the content of an answer to a request ({@code kind} given by its performative).
     *
     * @throws ContentException if it is not JSON or lacks the field its kind has
     */
    public static Reply parseReply(Reply.Kind kind, String content) throws ContentException {
        JsonNode reply;
        try {
            reply = MAPPER.readTree(content == null ? "" : content);
        } catch (JsonProcessingException e) {
            JsonLocation location = e.getLocation();
            throw new ContentException("malformed JSON: " + firstLine(e.getOriginalMessage()),
                    location == null ? 1 : Math.max(1, location.getLineNr()),
                    location == null ? 1 : Math.max(1, location.getColumnNr()));
        }
        if (reply == null || !reply.isObject()) {
            throw new ContentException("expected an object", 1, 1);
        }
        return switch (kind) {
            case RESULT -> new Reply.Result(required(reply, RESULT));
            case REFUSED -> new Reply.Refused(required(reply, REASON).asText());
            case FAILED -> new Reply.Failed(required(reply, EXCEPTION).asText(), reply.path(MESSAGE).textValue());
            case NOT_UNDERSTOOD -> new Reply.NotUnderstood(required(reply, ERROR).asText());
        };
    }

    private static JsonNode required(JsonNode reply, String field) throws ContentException {
        JsonNode value = reply.get(field);
        if (value == null) {
            throw new ContentException("missing field \"" + field + "\"", 1, 1);
        }
        return value;
    }

    private static ContentException at(JsonParser parser, String message) {
        return at(parser.currentTokenLocation(), message);
    }

    private static ContentException at(JsonLocation location, String message) {
        return new ContentException(message, location.getLineNr(), location.getColumnNr());
    }

    /** Jackson's message, first line, with its references to the source made readable. */
    private static String firstLine(String message) {
        int newline = message.indexOf('\n');
        String line = newline < 0 ? message : message.substring(0, newline);
        return SOURCE_REFERENCE.matcher(line).replaceAll("line $1, column $2");
    }
}
