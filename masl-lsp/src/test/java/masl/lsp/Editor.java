package masl.lsp;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import masl.runtime.descriptor.AgentPath;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CompletionCapabilities;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionItemCapabilities;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.TextDocumentClientCapabilities;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.LanguageClient;

/**
 * An editor talking to the server in-process: opens a program written with a cursor mark ({@value #CURSOR})
 * and asks what an editor asks at the mark. Diagnostics arrive on the server's checking thread; the editor
 * waits for them on a queue.
 */
final class Editor implements LanguageClient, AutoCloseable {

    static final String CURSOR = "‸";
    private static final long WAIT_SECONDS = 60;

    final MaslLanguageServer server = new MaslLanguageServer(AgentPath.parse(""), () -> { });
    /** Published and not yet taken by {@link #diagnostics}, in order; guarded by itself. */
    private final List<PublishDiagnosticsParams> published = new ArrayList<>();
    private final StringBuilder log = new StringBuilder();
    String uri = "file:///tmp/masl-lsp-test/program.masl";
    private String text;
    private Position cursor;

    Editor() {
        this(false);
    }

    Editor(boolean snippets) {
        server.connect(this);
        InitializeParams params = new InitializeParams();
        ClientCapabilities capabilities = new ClientCapabilities();
        TextDocumentClientCapabilities textDocument = new TextDocumentClientCapabilities();
        textDocument.setCompletion(new CompletionCapabilities(new CompletionItemCapabilities(snippets)));
        capabilities.setTextDocument(textDocument);
        params.setCapabilities(capabilities);
        server.initialize(params).join();
    }

    /** Opens {@code program}; its cursor mark, if any, is taken out and remembered. */
    Editor open(String program) {
        return open(uri, program);
    }

    Editor open(String documentUri, String program) {
        uri = documentUri;
        read(program);
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "masl", 1, text)));
        return this;
    }

    /** Replaces the whole text, as version {@code version}. */
    void replace(int version, String program) {
        read(program);
        server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(
                new VersionedTextDocumentIdentifier(uri, version), List.of(new TextDocumentContentChangeEvent(text))));
    }

    private void read(String program) {
        int mark = program.indexOf(CURSOR);
        text = program.replace(CURSOR, "");
        if (mark >= 0) {
            int line = (int) program.substring(0, mark).chars().filter(c -> c == '\n').count();
            cursor = new Position(line, mark - program.lastIndexOf('\n', mark - 1) - 1);
        }
    }

    List<CompletionItem> complete() {
        return server.getTextDocumentService().completion(new CompletionParams(new TextDocumentIdentifier(uri), cursor))
                .join().getLeft();
    }

    List<String> completionLabels() {
        return complete().stream().map(CompletionItem::getLabel).toList();
    }

    CompletionItem completion(String label) {
        return complete().stream().filter(item -> item.getLabel().equals(label)).findFirst()
                .orElseThrow(() -> new AssertionError("no completion " + label + " in " + completionLabels()));
    }

    /** The hover's Markdown, or null when there is none. */
    String hover() {
        Hover hover = server.getTextDocumentService().hover(new HoverParams(new TextDocumentIdentifier(uri), cursor)).join();
        return hover == null ? null : hover.getContents().getRight().getValue();
    }

    List<? extends Location> definition() {
        return server.getTextDocumentService().definition(new DefinitionParams(new TextDocumentIdentifier(uri), cursor))
                .join().getLeft();
    }

    List<DocumentSymbol> symbols() {
        return server.getTextDocumentService().documentSymbol(new DocumentSymbolParams(new TextDocumentIdentifier(uri)))
                .join().stream().map(Either::getRight).toList();
    }

    /** The diagnostics next published for {@code documentUri} (whatever its version), waiting for them. */
    PublishDiagnosticsParams diagnostics(String documentUri) throws InterruptedException, TimeoutException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(WAIT_SECONDS);
        synchronized (published) {
            while (true) {
                for (int i = 0; i < published.size(); i++) {
                    if (published.get(i).getUri().equals(documentUri)) {
                        return published.remove(i);
                    }
                }
                long left = deadline - System.nanoTime();
                if (left <= 0) {
                    throw new TimeoutException("no diagnostics for " + documentUri + "; log: " + log);
                }
                TimeUnit.NANOSECONDS.timedWait(published, left);
            }
        }
    }

    /** The position just after the first occurrence of {@code part} in the open text. */
    Position endOf(String part) {
        int end = text.indexOf(part) + part.length();
        int line = (int) text.substring(0, end).chars().filter(c -> c == '\n').count();
        return new Position(line, end - text.lastIndexOf('\n', end - 1) - 1);
    }

    /** The position of the first occurrence of {@code part}. */
    Position startOf(String part) {
        Position end = endOf(part);
        return new Position(end.getLine(), end.getCharacter() - part.length());
    }

    String log() {
        return log.toString();
    }

    @Override
    public void publishDiagnostics(PublishDiagnosticsParams diagnostics) {
        synchronized (published) {
            published.add(diagnostics);
            published.notifyAll();
        }
    }

    @Override
    public void logMessage(MessageParams message) {
        synchronized (log) {
            log.append(message.getMessage()).append('\n');
        }
    }

    @Override
    public void telemetryEvent(Object object) {
    }

    @Override
    public void showMessage(MessageParams message) {
        logMessage(message);
    }

    @Override
    public CompletableFuture<MessageActionItem> showMessageRequest(ShowMessageRequestParams request) {
        return CompletableFuture.completedFuture(null);
    }

    @Override
    public void close() {
        server.shutdown().join();
    }
}
