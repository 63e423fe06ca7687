package masl.lsp;

import com.google.gson.JsonElement;
import com.google.gson.JsonParseException;
import com.google.gson.JsonParser;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UnsupportedEncodingException;
import java.util.List;
import java.util.logging.Logger;
import org.eclipse.lsp4j.jsonrpc.MessageIssueHandler;
import org.eclipse.lsp4j.jsonrpc.json.MessageJsonHandler;
import org.eclipse.lsp4j.jsonrpc.json.StreamMessageProducer;
import org.eclipse.lsp4j.jsonrpc.messages.MessageIssue;
import org.eclipse.lsp4j.jsonrpc.messages.RequestMessage;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;

/**
 * Reads the editor's messages as LSP4J does, but takes each message's whole body (its
 * {@code Content-Length}) off the stream before parsing it: LSP4J parses straight from the stream and,
 * when a body is not one JSON object, leaves the rest of a long body there to be read as the next
 * headers, and every later request goes unanswered. A body that is not JSON is answered with
 * JSON-RPC's parse error, one that is not an object (a batch array, a number) with its invalid request;
 * either way the next message is read where it starts.
 */
final class WholeBodyMessageProducer extends StreamMessageProducer {

    private static final Logger LOG = Logger.getLogger(WholeBodyMessageProducer.class.getName());

    private final MessageIssueHandler answers;

    /** @param answers where an unreadable message is answered: the server's endpoint, which replies to the editor */
    WholeBodyMessageProducer(InputStream input, MessageJsonHandler json, MessageIssueHandler answers) {
        super(input, json, answers);
        this.answers = answers;
    }

    @Override
    protected boolean handleMessage(InputStream input, Headers headers) throws IOException {
        byte[] body = input.readNBytes(headers.contentLength);
        if (body.length < headers.contentLength) {
            return false;
        }
        MessageIssue problem;
        try {
            problem = problemOf(new String(body, headers.charset));
        } catch (UnsupportedEncodingException unknown) {
            problem = new MessageIssue("masl lsp: a message in an unknown charset: " + headers.charset,
                    ResponseErrorCode.ParseError.getValue());
        }
        if (problem != null) {
            answers.handle(new RequestMessage(), List.of(problem));
            return true;
        }
        return super.handleMessage(new ByteArrayInputStream(body), headers);
    }

    private static MessageIssue problemOf(String body) {
        JsonElement message;
        try {
            message = JsonParser.parseString(body);
        } catch (JsonParseException | StackOverflowError notJson) {
            return new MessageIssue("masl lsp: a message body that is not JSON", ResponseErrorCode.ParseError.getValue());
        }
        if (!message.isJsonObject()) {
            return new MessageIssue("masl lsp: a message must be one JSON object (JSON-RPC batches are not part of LSP)",
                    ResponseErrorCode.InvalidRequest.getValue());
        }
        return null;
    }

    /** A message LSP4J could not read: one line, without a stack trace, on the server's standard error. */
    @Override
    protected void fireError(Throwable error) {
        LOG.warning("masl lsp: a message was not understood: " + error.getMessage());
    }
}
