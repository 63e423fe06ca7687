package masl.jade.acl;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.TextNode;
import java.io.IOException;
import java.util.List;
import java.util.stream.Collectors;

/**
 * The content of requests to external FIPA agents and of their answers, in the two content
 * languages a descriptor may declare ({@code <Fipa language=…>}). {@code json}: the request is
 * MASL's own ({@code {"primitive": "divide", "args": [6, 3]}}), a result either {@code {"result": v}}
 * or the bare JSON value {@code v}. {@code string}: the request is the primitive's name and its
 * arguments, one space apart ({@code divide 6 3}); a result is the text itself for a {@code String},
 * else read as a JSON scalar ({@code 2}, {@code true}, {@code 2.5}). Nothing is ever deserialised into
 * a class the content names.
 */
public final class ForeignContent {

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final JsonFactory FACTORY = MAPPER.getFactory();

    private ForeignContent() {
    }

    /** A request's content in {@code language} ({@code json} or {@code string}). */
    public static String request(String language, String primitive, List<?> args) {
        if ("json".equals(language)) {
            return JsonContent.request(primitive, args);
        }
        return args.isEmpty() ? primitive
                : primitive + " " + args.stream().map(String::valueOf).collect(Collectors.joining(" "));
    }

    /**
     * The result an {@code INFORM} carries, as a value of {@code type}.
     *
     * @param what names the result in an error ("the result of calc.divide")
     * @throws ContentException positioned in the content, if it is not such a value
     */
    public static Object result(String language, String content, Class<?> type, String what) throws ContentException {
        String text = content == null ? "" : content;
        if ("string".equals(language) && type == String.class) {
            return text;
        }
        return JsonValues.fromJson(value(text, "json".equals(language)), type, what);
    }

    /** Where the value of {@code {"result": v}} starts: the object's first field. */
    private static JsonLocation resultLocation(String text) throws IOException {
        try (JsonParser parser = FACTORY.createParser(text)) {
            parser.nextToken();
            parser.nextToken();
            parser.nextToken();
            return parser.currentTokenLocation();
        }
    }

    private static Argument value(String text, boolean unwrapResult) throws ContentException {
        try (JsonParser parser = FACTORY.createParser(text)) {
            JsonToken first = parser.nextToken();
            if (first == null) {
                throw new ContentException("expected a value, got nothing", 1, 1);
            }
            JsonLocation start = parser.currentTokenLocation();
            JsonNode node = MAPPER.readTree(parser);
            if (parser.nextToken() != null) {
                JsonLocation after = parser.currentTokenLocation();
                throw new ContentException("unexpected text after the value", after.getLineNr(), after.getColumnNr());
            }
            if (unwrapResult && node.isObject() && node.size() == 1 && node.has(JsonContent.RESULT)) {
                JsonLocation result = resultLocation(text);
                return new Argument(node.get(JsonContent.RESULT), result.getLineNr(), result.getColumnNr());
            }
            return new Argument(node, start.getLineNr(), start.getColumnNr());
        } catch (JsonProcessingException malformed) {
            if (!unwrapResult) {
                // Plain text where a number or a boolean was expected: say so at its start.
                return new Argument(TextNode.valueOf(text), 1, 1);
            }
            JsonLocation location = malformed.getLocation();
            throw new ContentException("malformed JSON: " + malformed.getOriginalMessage().lines().findFirst()
                    .orElse(""), location == null ? 1 : Math.max(1, location.getLineNr()),
                    location == null ? 1 : Math.max(1, location.getColumnNr()));
        } catch (IOException unreadable) {
            throw new ContentException("unreadable content: " + unreadable.getMessage(), 1, 1);
        }
    }
}
