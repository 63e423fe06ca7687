package masl.jade.acl;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The JSON content of invocation messages: round trips, and every malformed request, positioned. */
class JsonContentTest {

    @Test
    void aRequestRoundTrips() throws Exception {
        String content = JsonContent.request("move", List.of(3, 2.5, "fast", true, 'x', new int[] {1, 2}));
        assertEquals("{\"primitive\":\"move\",\"args\":[3,2.5,\"fast\",true,\"x\",[1,2]]}", content);
        InvocationRequest request = JsonContent.parseRequest(content);
        assertEquals("move", request.primitive());
        assertEquals(List.of("3", "2.5", "\"fast\"", "true", "\"x\"", "[1,2]"),
                request.args().stream().map(argument -> argument.value().toString()).toList());
    }

    @Test
    void argumentsKnowWhereTheyStart() throws Exception {
        InvocationRequest request = JsonContent.parseRequest("{\"primitive\": \"log\",\n \"args\": [1,\n  \"two\"]}");
        assertEquals(List.of(2, 3), request.args().stream().map(Argument::line).toList());
        assertEquals(List.of(11, 3), request.args().stream().map(Argument::column).toList());
    }

    @Test
    void argsMayBeLeftOutWhenThereAreNone() throws Exception {
        assertEquals(new InvocationRequest("nop", 1, 14, List.of()),
                JsonContent.parseRequest("{\"primitive\":\"nop\"}"));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            {primitive:"log"} | content:1:2: error: malformed JSON: Unexpected character ('p' (code 112)): \
            was expecting double-quote to start field name
            ["log"] | content:1:1: error: expected an object {"primitive": name, "args": [...]}
            "log" | content:1:1: error: expected an object {"primitive": name, "args": [...]}
            {"args":[]} | content:1:1: error: missing field "primitive": the name of the primitive to invoke
            {"primitive":7} | content:1:14: error: "primitive" must be a primitive's name, a non-empty string
            {"primitive":""} | content:1:14: error: "primitive" must be a primitive's name, a non-empty string
            {"primitive":"log","args":"a"} | content:1:27: error: "args" must be an array of the arguments
            {"primitive":"log","member":"x"} | content:1:20: error: unknown field "member": \
            a request has only "primitive" and "args"
            {"primitive":"log","primitive":"nop"} | content:1:20: error: duplicate field "primitive"
            {"primitive":"log"} {"primitive":"nop"} | content:1:21: error: unexpected content after the request object
            """)
    void malformedRequestsArePositioned(String content, String error) {
        ContentException problem = assertThrows(ContentException.class,
                () -> JsonContent.parseRequest(content.strip()));
        assertEquals(error, problem.describe());
    }

    @Test
    void truncatedContentNamesWhereTheOpenObjectStarts() {
        assertEquals("content:1:32: error: malformed JSON: Unexpected end-of-input: expected close marker for "
                + "Object (start marker at line 1, column 1)", assertThrows(ContentException.class,
                        () -> JsonContent.parseRequest("{\"primitive\":\"log\",\"args\":[\"a\"]")).describe());
    }

    @Test
    void emptyContentIsNotARequest() {
        assertEquals("content:1:1: error: empty content: expected {\"primitive\": name, \"args\": [...]}",
                assertThrows(ContentException.class, () -> JsonContent.parseRequest(null)).describe());
        assertEquals(1, assertThrows(ContentException.class, () -> JsonContent.parseRequest("  ")).line());
    }

    @Test
    void aSyntaxErrorOnALaterLineNamesThatLine() {
        ContentException problem = assertThrows(ContentException.class,
                () -> JsonContent.parseRequest("{\"primitive\": \"log\",\n  \"args\": [1,,2]}"));
        assertEquals(2, problem.line());
        assertEquals(14, problem.column());
    }

    @Test
    void everyReplyRoundTrips() throws Exception {
        assertEquals(new Reply.Result(json("42")),
                JsonContent.parseReply(Reply.Kind.RESULT, JsonContent.result(42)));
        assertEquals(new Reply.Result(json("null")),
                JsonContent.parseReply(Reply.Kind.RESULT, JsonContent.result(null)));
        assertEquals(new Reply.Refused("denied by state nothing"),
                JsonContent.parseReply(Reply.Kind.REFUSED, JsonContent.refusal("denied by state nothing")));
        assertEquals(new Reply.Failed("java.lang.ArithmeticException", "/ by zero"),
                JsonContent.parseReply(Reply.Kind.FAILED, JsonContent.failure(new ArithmeticException("/ by zero"))));
        assertEquals(new Reply.Failed("java.lang.IllegalStateException", null),
                JsonContent.parseReply(Reply.Kind.FAILED, JsonContent.failure(new IllegalStateException())));
        ContentException problem = new ContentException("unknown primitive \"fly\"", 1, 14);
        assertEquals(new Reply.NotUnderstood("content:1:14: error: unknown primitive \"fly\""),
                JsonContent.parseReply(Reply.Kind.NOT_UNDERSTOOD, JsonContent.notUnderstood(problem)));
    }

    @Test
    void aReplyWithoutItsFieldIsMalformed() {
        assertEquals("content:1:1: error: missing field \"result\"",
                assertThrows(ContentException.class, () -> JsonContent.parseReply(Reply.Kind.RESULT, "{}")).describe());
        assertEquals(1, assertThrows(ContentException.class,
                () -> JsonContent.parseReply(Reply.Kind.REFUSED, "{\"reason\":")).line());
        assertEquals("content:1:1: error: expected an object",
                assertThrows(ContentException.class, () -> JsonContent.parseReply(Reply.Kind.RESULT, "[]")).describe());
    }

    @Test
    void resultsAreWrittenAsJsonValuesNeverAsBeans() {
        assertEquals("{\"result\":[1,2,3]}", JsonContent.result(new int[] {1, 2, 3}));
        assertEquals("{\"result\":[\"a\",null]}", JsonContent.result(Arrays.asList("a", null)));
        assertEquals("{\"result\":{\"k\":2.5}}", JsonContent.result(Map.of("k", 2.5)));
        assertEquals("{\"result\":\"c\"}", JsonContent.result('c'));
        assertEquals("{\"result\":\"point(1,2)\"}", JsonContent.result(new Object() {
            @Override
            public String toString() {
                return "point(1,2)";
            }
        }));
    }

    @Test
    void argumentsConvertToTheParameterTypes() throws Exception {
        assertEquals(7, convert("7", int.class));
        assertEquals(7L, convert("7", long.class));
        assertEquals((short) -3, convert("-3", short.class));
        assertEquals((byte) 100, convert("100", byte.class));
        assertEquals(7.0, convert("7", double.class));
        assertEquals(0.5f, convert("0.5", float.class));
        assertEquals(true, convert("true", boolean.class));
        assertEquals('q', convert("\"q\"", char.class));
        assertEquals("12", convert("12", String.class), "MASL §3: a value where a String is expected");
        assertEquals("true", convert("true", String.class));
        assertNull(convert("null", String.class));
        assertArrayEquals(new double[] {1, 2.5}, (double[]) convert("[1, 2.5]", double[].class));
        assertArrayEquals(new String[] {"a", "b"}, (String[]) convert("[\"a\", \"b\"]", String[].class));
        assertEquals(List.of(1, "x", Map.of("k", false)), convert("[1, \"x\", {\"k\": false}]", Object.class));
        assertEquals(5_000_000_000L, convert("5000000000", Object.class));
    }

    @ParameterizedTest
    @CsvSource(delimiter = '|', textBlock = """
            "7" | int      | content:1:5: error: argument 1 of f: expected an int, got "7"
            2.5 | int      | content:1:5: error: argument 1 of f: expected an int, got 2.5
            3000000000 | int      | content:1:5: error: argument 1 of f: expected an int, got 3000000000
            200 | byte     | content:1:5: error: argument 1 of f: expected a byte, got 200
            null | double   | content:1:5: error: argument 1 of f: expected a double, got null
            1            | boolean | content:1:5: error: argument 1 of f: expected a boolean, got 1
            "ab" | char     | content:1:5: error: argument 1 of f: expected a char (a one-character string), got "ab"
            [1] | String   | content:1:5: error: argument 1 of f: expected a string (or number or boolean), got [1]
            [1,"x"] | int[]    | content:1:5: error: argument 1 of f: expected an array of int values, got [1,"x"]
            {} | Thread   | content:1:5: error: argument 1 of f: expected a Thread, got {}
            """)
    void argumentsOfTheWrongTypeArePositioned(String json, String typeName, String error) throws Exception {
        Class<?> type = switch (typeName) {
            case "int" -> int.class;
            case "byte" -> byte.class;
            case "double" -> double.class;
            case "boolean" -> boolean.class;
            case "char" -> char.class;
            case "String" -> String.class;
            case "int[]" -> int[].class;
            default -> Thread.class;
        };
        Argument argument = new Argument(json(json), 1, 5);
        assertEquals(error, assertThrows(ContentException.class,
                () -> JsonValues.fromJson(argument, type, "argument 1 of f")).describe());
    }

    private static Object convert(String json, Class<?> type) throws Exception {
        return JsonValues.fromJson(new Argument(json(json), 1, 1), type, "argument");
    }

    private static JsonNode json(String text) throws Exception {
        return new ObjectMapper().readTree(text);
    }
}
