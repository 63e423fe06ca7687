package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import masl.runtime.descriptor.AgentPath;
import org.junit.jupiter.api.Test;

/**
 * The server answers every well-framed message, whatever its body: a body that is not one JSON object
 * gets a JSON-RPC error, and the messages after it are read where they start. A JSON array over
 * LSP4J's 8 KB of read-ahead used to leave its tail on the stream, read as the next headers, so that
 * no later request was answered.
 */
class MessageFramingTest {

    @Test
    void everyWellFramedMessageIsAnsweredWhateverItsBody() throws Exception {
        StringBuilder batch = new StringBuilder("[");
        for (int i = 0; i < 300; i++) {
            batch.append(i == 0 ? "" : ",").append("{\"jsonrpc\":\"2.0\",\"id\":").append(100 + i).append(",\"method\":\"shutdown\"}");
        }
        batch.append("]");
        ByteArrayOutputStream editor = new ByteArrayOutputStream();
        frame(editor, "{\"jsonrpc\":\"2.0\",\"id\":1,\"method\":\"initialize\",\"params\":{\"capabilities\":{}}}");
        frame(editor, batch.toString());
        frame(editor, "{\"jsonrpc\":\"2.0\",\"id\":2,\"method\":\"initialize\",\"params\":{\"capab");
        frame(editor, "42");
        frame(editor, "{\"jsonrpc\":\"2.0\",\"id\":3,\"method\":\"shutdown\"}");
        frame(editor, "{\"jsonrpc\":\"2.0\",\"method\":\"exit\"}");
        ByteArrayOutputStream server = new ByteArrayOutputStream();

        int status = MaslLsp.serve(new ByteArrayInputStream(editor.toByteArray()), server, AgentPath.parse(""));

        List<JsonObject> answers = messages(server.toString(StandardCharsets.UTF_8));
        assertEquals(List.of("id 1: result", "error -32600", "error -32700", "error -32600", "id 3: result"),
                answers.stream().map(MessageFramingTest::summary).toList(), answers::toString);
        assertEquals(0, status, "the session ended with shutdown and exit");
    }

    private static String summary(JsonObject answer) {
        if (answer.has("error")) {
            return "error " + answer.getAsJsonObject("error").get("code").getAsInt();
        }
        return "id " + answer.get("id").getAsInt() + ": " + (answer.has("result") ? "result" : "?");
    }

    private static void frame(ByteArrayOutputStream to, String body) {
        byte[] bytes = body.getBytes(StandardCharsets.UTF_8);
        to.writeBytes(("Content-Length: " + bytes.length + "\r\n\r\n").getBytes(StandardCharsets.US_ASCII));
        to.writeBytes(bytes);
    }

    /** The messages of a stream of framed messages, in order. */
    private static List<JsonObject> messages(String stream) {
        List<JsonObject> messages = new ArrayList<>();
        int at = 0;
        while (at < stream.length()) {
            int headersEnd = stream.indexOf("\r\n\r\n", at);
            int length = Integer.parseInt(stream.substring(at, headersEnd).replaceAll("(?s).*Content-Length: (\\d+).*", "$1"));
            int bodyStart = headersEnd + 4;
            String body = new String(stream.substring(bodyStart).getBytes(StandardCharsets.UTF_8), 0, length, StandardCharsets.UTF_8);
            messages.add(JsonParser.parseString(body).getAsJsonObject());
            at = bodyStart + body.length();
        }
        return messages;
    }
}
