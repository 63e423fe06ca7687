package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code masl lsp} as an editor meets it: the command runs with its standard input and output
 * piped to an LSP4J client, which opens a program, edits it and asks for completion, hover and definitions.
 */
class LspCommandTest {

    private static final long WAIT_SECONDS = 60;
    private static final Pattern HEADLINE = Pattern.compile("(.*):(\\d+):(\\d+): error: (.*)");

    /** Two errors the analysis finds: a name no block declares, a primitive no type has. */
    private static final String TWO_ERRORS = """
            import Default.xml as Default;
            Default a, b = newAgent(Default);
            asynchronous entry main (true) {
              local int n = 0;
              asynchronous entry work (.getProxyID() > 0) {
                n = n + undeclared;
                .lgo("x");
                break(work);
              }
            }
            """;
    private static final String FIXED = TWO_ERRORS.replace("undeclared", "1").replace(".lgo", ".logln");

    @TempDir
    Path folder;

    private final BlockingQueue<PublishDiagnosticsParams> published = new LinkedBlockingQueue<>();
    private final ByteArrayOutputStream serverErr = new ByteArrayOutputStream();
    private CompletableFuture<Integer> status;
    private LanguageServer server;
    private final MemoryPipe toServer = new MemoryPipe();
    private final MemoryPipe toClient = new MemoryPipe();

    @BeforeEach
    void startMaslLsp() throws Exception {
        PrintStream serverOut = new PrintStream(toClient.out, true, StandardCharsets.UTF_8);
        PrintStream err = new PrintStream(serverErr, true, StandardCharsets.UTF_8);
        status = CompletableFuture.supplyAsync(() -> new Masl(toServer.in, serverOut, err).run("lsp"));
        Launcher<LanguageServer> launcher = LSPLauncher.createClientLauncher(new RecordingClient(), toClient.in,
                toServer.out);
        launcher.startListening();
        server = launcher.getRemoteProxy();
        InitializeParams initialize = new InitializeParams();
        initialize.setCapabilities(new ClientCapabilities());
        initialize.setRootUri(folder.toUri().toString());
        server.initialize(initialize).get(WAIT_SECONDS, TimeUnit.SECONDS);
        server.initialized(new InitializedParams());
    }

    @AfterEach
    void endTheSession() throws Exception {
        server.shutdown().get(WAIT_SECONDS, TimeUnit.SECONDS);
        server.exit();
        assertEquals(0, status.get(WAIT_SECONDS, TimeUnit.SECONDS), serverErr.toString(StandardCharsets.UTF_8));
        toServer.close();
        toClient.close();
    }

    @Test
    void diagnosticsAreMaslChecksAndAnEditClearsThem() throws Exception {
        Path program = write("two-errors.masl", TWO_ERRORS);
        List<String> check = maslCheck(program);
        assertEquals(2, check.size(), "masl check finds two errors: " + check);

        String uri = open(program, TWO_ERRORS);
        assertEquals(check, messages(diagnosticsOf(uri, 1)));

        change(uri, 2, FIXED);
        assertEquals(List.of(), diagnosticsOf(uri, 2));

        // A construct the translator refuses: an error of masl check's translation, not of the analysis.
        String refused = FIXED.replace("break(work);",
                "if (java.nio.file.Files.size(java.nio.file.Path.of(\"x\")) > 0) .nop();");
        List<String> refusal = maslCheck(write("refused.masl", refused));
        assertEquals(1, refusal.size(), refusal.toString());
        change(uri, 3, refused);
        assertEquals(refusal, messages(diagnosticsOf(uri, 3)));

        // Syntax errors and the analysis's errors of the same file, in one publication, as masl check has them.
        String mistyped = TWO_ERRORS.replace("local int n = 0;", "locl int n = 0").replace("break(work);", "break(work)");
        List<String> mistakes = maslCheck(write("mistyped.masl", mistyped));
        assertEquals(5, mistakes.size(), mistakes.toString());
        change(uri, 4, mistyped);
        assertEquals(mistakes, messages(diagnosticsOf(uri, 4)));
    }

    private static List<String> messages(List<Diagnostic> diagnostics) {
        return diagnostics.stream().map(d -> (d.getRange().getStart().getLine() + 1) + ":"
                + (d.getRange().getStart().getCharacter() + 1) + ": " + d.getMessage()).toList();
    }

    @Test
    void completesAnAgentsPrimitivesWithTheirSignatures() throws Exception {
        String text = FIXED.replace("    .logln(\"x\");\n", "    .lo\n");
        Path program = write("typing.masl", text);
        String uri = open(program, text);
        List<CompletionItem> items = server.getTextDocumentService()
                .completion(new CompletionParams(new TextDocumentIdentifier(uri), endOf(text, ".lo")))
                .get(WAIT_SECONDS, TimeUnit.SECONDS).getLeft();
        Map<String, String> signatures = new java.util.HashMap<>();
        items.forEach(item -> signatures.put(item.getLabel(), item.getDetail()));
        assertEquals("void log(String message)", signatures.get("log"), items.toString());
        assertEquals("void logln(String message)", signatures.get("logln"), items.toString());
    }

    @Test
    void hoverDescribesAPrimitive() throws Exception {
        Path program = write("hover.masl", FIXED);
        String uri = open(program, FIXED);
        Hover hover = server.getTextDocumentService()
                .hover(new HoverParams(new TextDocumentIdentifier(uri), endOf(FIXED, ".log")))
                .get(WAIT_SECONDS, TimeUnit.SECONDS);
        assertNotNull(hover, "no hover on logln");
        String text = hover.getContents().getRight().getValue();
        assertTrue(text.contains("void logln(String message)"), text);
        assertTrue(text.contains("**synchronous**"), text);
        assertTrue(text.contains("*user (the agent itself)*: default"), text);
        assertTrue(text.contains("*other*: default"), text);
    }

    @Test
    void jumpsFromABreakToItsEntryAndFromAnImportToTheDescriptor() throws Exception {
        Path program = write("jumps.masl", FIXED);
        String uri = open(program, FIXED);

        List<? extends Location> toEntry = definition(uri, endOf(FIXED, "break(wo"));
        assertEquals(1, toEntry.size(), toEntry.toString());
        assertEquals(uri, toEntry.get(0).getUri());
        assertEquals(endOf(FIXED, "  asynchronous entry "), toEntry.get(0).getRange().getStart());

        List<? extends Location> toDescriptor = definition(uri, endOf(FIXED, "import Def"));
        assertEquals(1, toDescriptor.size(), toDescriptor.toString());
        Path descriptor = Path.of(URI.create(toDescriptor.get(0).getUri()));
        assertEquals("Default.xml", descriptor.getFileName().toString());
        String line = Files.readAllLines(descriptor).get(toDescriptor.get(0).getRange().getStart().getLine());
        assertTrue(line.startsWith("<Agent short_class_name=\"Default\""), line);
    }

    private List<? extends Location> definition(String uri, Position position) throws Exception {
        return server.getTextDocumentService()
                .definition(new DefinitionParams(new TextDocumentIdentifier(uri), position))
                .get(WAIT_SECONDS, TimeUnit.SECONDS).getLeft();
    }

    /**
     * {@code line:column: text} of each error {@code masl check} prints for the program: the headline's
     * message and every further line it prints for the error but the source line and its caret (a hint, say),
     * which the editor must show too.
     */
    private List<String> maslCheck(Path program) throws IOException {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        new Masl(new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, StandardCharsets.UTF_8))
                .run("check", program.toString());
        List<String> source = Files.readAllLines(program);
        List<String> errors = new ArrayList<>();
        for (String line : err.toString(StandardCharsets.UTF_8).split("\n")) {
            Matcher headline = HEADLINE.matcher(line);
            if (headline.matches()) {
                assertEquals(program.toString(), headline.group(1));
                errors.add(headline.group(2) + ":" + headline.group(3) + ": " + headline.group(4));
            } else if (!errors.isEmpty() && !line.matches("\\d+ errors?") && !source.contains(line)
                    && !line.matches("[ \\t]*\\^")) {
                errors.set(errors.size() - 1, errors.get(errors.size() - 1) + "\n" + line);
            }
        }
        return errors;
    }

    private String open(Path program, String text) {
        String uri = program.toUri().toString();
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "masl", 1, text)));
        return uri;
    }

    private void change(String uri, int version, String text) {
        server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(
                new VersionedTextDocumentIdentifier(uri, version), List.of(new TextDocumentContentChangeEvent(text))));
    }

    /** The diagnostics published for that version of the document, waiting for them. */
    private List<Diagnostic> diagnosticsOf(String uri, int version) throws InterruptedException, TimeoutException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(WAIT_SECONDS);
        while (System.nanoTime() < deadline) {
            PublishDiagnosticsParams params = published.poll(deadline - System.nanoTime(), TimeUnit.NANOSECONDS);
            if (params != null && params.getUri().equals(uri) && Integer.valueOf(version).equals(params.getVersion())) {
                return params.getDiagnostics();
            }
        }
        throw new TimeoutException("no diagnostics for version " + version + " of " + uri);
    }

    /** The position just after the first occurrence of {@code text}. */
    private static Position endOf(String document, String text) {
        int end = document.indexOf(text) + text.length();
        int line = (int) document.substring(0, end).chars().filter(c -> c == '\n').count();
        return new Position(line, end - document.lastIndexOf('\n', end - 1) - 1);
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(folder.resolve(name), text);
    }

    /** A client that keeps the diagnostics it is sent. */
    private final class RecordingClient implements LanguageClient {
        @Override
        public void publishDiagnostics(PublishDiagnosticsParams diagnostics) {
            published.add(diagnostics);
        }

        @Override
        public void telemetryEvent(Object object) {
        }

        @Override
        public void showMessage(MessageParams message) {
        }

        @Override
        public CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams request) {
            return CompletableFuture.completedFuture(null);
        }

        @Override
        public void logMessage(MessageParams message) {
            serverErr.writeBytes((message.getMessage() + "\n").getBytes(StandardCharsets.UTF_8));
        }
    }
}
