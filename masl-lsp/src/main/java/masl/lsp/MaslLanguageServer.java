package masl.lsp;

import java.util.List;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import masl.runtime.descriptor.AgentPath;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CompletionCapabilities;
import org.eclipse.lsp4j.CompletionItemCapabilities;
import org.eclipse.lsp4j.CompletionOptions;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.ServerInfo;
import org.eclipse.lsp4j.TextDocumentClientCapabilities;
import org.eclipse.lsp4j.TextDocumentSyncKind;
import org.eclipse.lsp4j.TextDocumentSyncOptions;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageClientAware;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.lsp4j.services.TextDocumentService;
import org.eclipse.lsp4j.services.WorkspaceService;

/**
 * The MASL language server: diagnostics, completion, hover, go to definition, the outline and folding of
 * MASL programs. {@link MaslLsp#serve} runs it over a pair of streams.
 */
public final class MaslLanguageServer implements LanguageServer, LanguageClientAware {

    private final MaslTextDocuments documents;
    private final MaslWorkspace workspace;
    private final Runnable onExit;
    private volatile LanguageClient client;
    private volatile boolean shutDown;

    /**
     * @param agentPath where descriptors are looked up after the program's folder, as {@code --agent-path} says
     * @param onExit what the {@code exit} notification does: stop serving
     */
    public MaslLanguageServer(AgentPath agentPath, Runnable onExit) {
        this.onExit = onExit;
        this.documents = new MaslTextDocuments(agentPath, () -> client);
        this.workspace = new MaslWorkspace(documents);
    }

    @Override
    public void connect(LanguageClient languageClient) {
        this.client = languageClient;
    }

    @Override
    public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
        documents.setSnippets(snippetSupport(params));
        TextDocumentSyncOptions sync = new TextDocumentSyncOptions();
        sync.setOpenClose(true);
        sync.setChange(TextDocumentSyncKind.Incremental);
        ServerCapabilities capabilities = new ServerCapabilities();
        capabilities.setTextDocumentSync(sync);
        CompletionOptions completion = new CompletionOptions(false, List.of(".", "("));
        capabilities.setCompletionProvider(completion);
        capabilities.setHoverProvider(true);
        capabilities.setDefinitionProvider(true);
        capabilities.setDocumentSymbolProvider(true);
        capabilities.setFoldingRangeProvider(true);
        return CompletableFuture.completedFuture(new InitializeResult(capabilities, new ServerInfo("masl lsp",
                MaslLanguageServer.class.getPackage().getImplementationVersion())));
    }

    private static boolean snippetSupport(InitializeParams params) {
        return Optional.ofNullable(params.getCapabilities()).map(ClientCapabilities::getTextDocument)
                .map(TextDocumentClientCapabilities::getCompletion).map(CompletionCapabilities::getCompletionItem)
                .map(CompletionItemCapabilities::getSnippetSupport).orElse(false);
    }

    @Override
    public CompletableFuture<Object> shutdown() {
        shutDown = true;
        documents.close();
        return CompletableFuture.completedFuture(null);
    }

    @Override
    public void exit() {
        documents.close();
        onExit.run();
    }

    /** Whether the client asked for a shutdown before exit, as LSP's clean ending requires. */
    public boolean wasShutDown() {
        return shutDown;
    }

    @Override
    public TextDocumentService getTextDocumentService() {
        return documents;
    }

    @Override
    public WorkspaceService getWorkspaceService() {
        return workspace;
    }
}
