package masl.lsp;

import org.eclipse.lsp4j.DidChangeConfigurationParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.services.WorkspaceService;

/** Workspace events: a descriptor that changes on disk changes what the open programs mean. */
final class MaslWorkspace implements WorkspaceService {

    private final MaslTextDocuments documents;

    MaslWorkspace(MaslTextDocuments documents) {
        this.documents = documents;
    }

    @Override
    public void didChangeWatchedFiles(DidChangeWatchedFilesParams params) {
        boolean descriptor = params.getChanges().stream().anyMatch(change -> change.getUri().endsWith(".xml"));
        if (descriptor) {
            documents.descriptorsChanged();
        }
    }

    @Override
    public void didChangeConfiguration(DidChangeConfigurationParams params) {
        // The agent path is given on the command line (masl lsp --agent-path): there is nothing to configure.
    }
}
