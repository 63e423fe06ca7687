package masl.lsp;

import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;
import java.util.function.Supplier;
import masl.runtime.descriptor.AgentPath;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidCloseTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DidSaveTextDocumentParams;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.FoldingRange;
import org.eclipse.lsp4j.FoldingRangeRequestParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.SymbolInformation;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.TextDocumentService;

/**
 * The open programs: their text as the editor has it, checked on every change ({@link DiagnosticsPublisher}),
 * and the requests about them. A request is answered from the {@link ProgramIndex} of the document's current
 * version, built on the first request after a change, so that typing pays for the check alone.
 */
final class MaslTextDocuments implements TextDocumentService {

    /** A document and the index built from it. */
    private record Indexed(TextDocument document, ProgramIndex index) { }

    private final AgentPath agentPath;
    private final Supplier<LanguageClient> client;
    private final DiagnosticsPublisher diagnostics;
    private final Map<String, TextDocument> open = new ConcurrentHashMap<>();
    private final Map<String, Indexed> indexes = new ConcurrentHashMap<>();
    private volatile boolean snippets;

    MaslTextDocuments(AgentPath agentPath, Supplier<LanguageClient> client) {
        this.agentPath = agentPath;
        this.client = client;
        this.diagnostics = new DiagnosticsPublisher(() -> agentPath, client);
    }

    void setSnippets(boolean snippets) {
        this.snippets = snippets;
    }

    @Override
    public void didOpen(DidOpenTextDocumentParams params) {
        TextDocument document = new TextDocument(params.getTextDocument().getUri(), params.getTextDocument().getVersion(),
                params.getTextDocument().getText());
        open.put(document.uri(), document);
        diagnostics.check(document);
    }

    @Override
    public void didChange(DidChangeTextDocumentParams params) {
        TextDocument document = open.computeIfPresent(params.getTextDocument().getUri(),
                (uri, current) -> current.edited(params.getTextDocument().getVersion(), params.getContentChanges()));
        if (document != null) {
            diagnostics.check(document);
        }
    }

    @Override
    public void didClose(DidCloseTextDocumentParams params) {
        String uri = params.getTextDocument().getUri();
        open.remove(uri);
        indexes.remove(uri);
        diagnostics.closed(uri);
    }

    @Override
    public void didSave(DidSaveTextDocumentParams params) {
        // Every change is checked as it is made: saving adds nothing.
    }

    /** A descriptor changed on disk: every open program is checked again and indexed anew. */
    void descriptorsChanged() {
        indexes.clear();
        open.values().forEach(diagnostics::check);
    }

    @Override
    public CompletableFuture<Either<List<CompletionItem>, CompletionList>> completion(CompletionParams params) {
        return answer(params.getTextDocument().getUri(), params.getPosition(), List.<CompletionItem>of(),
                cursor -> Completions.at(cursor, snippets)).thenApply(Either::forLeft);
    }

    @Override
    public CompletableFuture<Hover> hover(org.eclipse.lsp4j.HoverParams params) {
        return answer(params.getTextDocument().getUri(), params.getPosition(), null,
                cursor -> Hovers.at(cursor).orElse(null));
    }

    @Override
    public CompletableFuture<Either<List<? extends Location>, List<? extends LocationLink>>> definition(
            DefinitionParams params) {
        return answer(params.getTextDocument().getUri(), params.getPosition(), List.<Location>of(), Definitions::at)
                .thenApply(Either::forLeft);
    }

    @Override
    public CompletableFuture<List<Either<SymbolInformation, DocumentSymbol>>> documentSymbol(
            DocumentSymbolParams params) {
        String uri = params.getTextDocument().getUri();
        return answer(uri, new Position(0, 0), List.<DocumentSymbol>of(),
                cursor -> Outline.of(cursor.index, cursor.document))
                .thenApply(symbols -> symbols.stream().map(Either::<SymbolInformation, DocumentSymbol>forRight).toList());
    }

    @Override
    public CompletableFuture<List<FoldingRange>> foldingRange(FoldingRangeRequestParams params) {
        return answer(params.getTextDocument().getUri(), new Position(0, 0), List.<FoldingRange>of(),
                cursor -> Folding.of(cursor.index));
    }

    /**
     * Answers a request about an open document from its current version; {@code none} for a document that is
     * not open, or when answering fails (the failure is logged to the client: an editor feature going quiet
     * must not end the session).
     */
    private <T> CompletableFuture<T> answer(String uri, Position position, T none, Function<Cursor, T> answer) {
        TextDocument document = open.get(uri);
        if (document == null) {
            return CompletableFuture.completedFuture(none);
        }
        try {
            return CompletableFuture.completedFuture(answer.apply(new Cursor(index(document), document, position)));
        } catch (RuntimeException | StackOverflowError bug) {
            LanguageClient languageClient = client.get();
            if (languageClient != null) {
                languageClient.logMessage(new MessageParams(MessageType.Error,
                        "masl lsp: internal error, please report it: " + bug));
            }
            return CompletableFuture.completedFuture(none);
        }
    }

    private ProgramIndex index(TextDocument document) {
        Indexed indexed = indexes.get(document.uri());
        if (indexed == null || indexed.document() != document) {
            indexed = new Indexed(document, ProgramIndex.of(document.source(), agentPath));
            indexes.put(document.uri(), indexed);
        }
        return indexed.index();
    }

    void close() {
        diagnostics.close();
    }
}
