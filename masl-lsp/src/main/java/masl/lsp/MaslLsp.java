package masl.lsp;

import java.io.InputStream;
import java.io.OutputStream;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicReference;
import masl.runtime.descriptor.AgentPath;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.services.LanguageClient;

/** Runs the MASL language server over a pair of streams: what {@code masl lsp} does on standard input and output. */
public final class MaslLsp {

    private MaslLsp() {
    }

    /**
     * Serves until the client sends {@code exit} or closes {@code in}.
     *
     * @return the exit status LSP prescribes: 0 after a {@code shutdown} request, 1 otherwise
     */
    public static int serve(InputStream in, OutputStream out, AgentPath agentPath) throws InterruptedException {
        AtomicReference<Future<Void>> listening = new AtomicReference<>();
        MaslLanguageServer server = new MaslLanguageServer(agentPath, () -> listening.get().cancel(true));
        OneLineLog.install();
        Launcher<LanguageClient> launcher = new WholeBodyLauncherBuilder().setLocalService(server)
                .setRemoteInterface(LanguageClient.class).setInput(in).setOutput(out).create();
        server.connect(launcher.getRemoteProxy());
        listening.set(launcher.startListening());
        try {
            listening.get().get();
        } catch (CancellationException exited) {
            // The exit notification: the normal end.
        } catch (ExecutionException streamFailed) {
            // The client went away without exit: the end of the session all the same.
        }
        return server.wasShutDown() ? 0 : 1;
    }
}
