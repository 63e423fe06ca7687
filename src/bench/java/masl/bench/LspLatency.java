package masl.bench;

import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import masl.lsp.MaslLsp;
import masl.runtime.descriptor.AgentPath;
import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.MessageActionItem;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.ShowMessageRequestParams;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.TextDocumentItem;
import org.eclipse.lsp4j.VersionedTextDocumentIdentifier;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageServer;

/**
 * How long an editor waits for {@code masl lsp}'s diagnostics after a change to a
 * 10,000-line program (the translation benchmark's). The server runs in this JVM behind LSP4J's JSON-RPC over
 * piped streams, as {@code masl lsp} does over standard input and output; each change is one line edited
 * (alternately breaking and repairing a name), timed from sending {@code didChange} to receiving the
 * {@code publishDiagnostics} of that version, which must hold one error after a break and none after a repair.
 */
final class LspLatency {

    static final int LINES = 10_000;
    private static final int WARM_UP_CHANGES = 20;
    private static final int MEASURED_CHANGES = 40;

    /**
     * Milliseconds per measured change; the process's CPU time per measured change, every thread (server,
     * JSON-RPC, client) included, which other jobs on the machine change much less than elapsed time; and
     * the first check of the program, when it is opened in a fresh JVM.
     */
    record Figures(double[] changes, double cpuPerChange, double open) { }

    private LspLatency() {
    }

    static Figures measure() throws Exception {
        String program = MaslTranslation.source(LINES);
        List<String> lines = program.lines().toList();
        int edited = lines.indexOf("  total++;") + lines.size() / 2;
        while (!lines.get(edited).equals("  total++;")) {
            edited++;
        }
        Path folder = Files.createTempDirectory("masl-lsp-bench");
        String uri = folder.resolve("big.masl").toUri().toString();

        BlockingQueue<PublishDiagnosticsParams> published = new LinkedBlockingQueue<>();
        PipedInputStream serverIn = new PipedInputStream(1 << 20);
        PipedOutputStream toServer = new PipedOutputStream(serverIn);
        PipedInputStream clientIn = new PipedInputStream(1 << 20);
        PipedOutputStream fromServer = new PipedOutputStream(clientIn);
        CompletableFuture<Integer> serving = CompletableFuture.supplyAsync(() -> {
            try {
                return MaslLsp.serve(serverIn, fromServer, AgentPath.parse(""));
            } catch (InterruptedException interrupted) {
                Thread.currentThread().interrupt();
                return -1;
            }
        });
        Launcher<LanguageServer> launcher = LSPLauncher.createClientLauncher(new Client(published), clientIn, toServer);
        launcher.startListening();
        LanguageServer server = launcher.getRemoteProxy();
        InitializeParams initialize = new InitializeParams();
        initialize.setCapabilities(new ClientCapabilities());
        server.initialize(initialize).get(60, TimeUnit.SECONDS);
        server.initialized(new InitializedParams());

        long start = System.nanoTime();
        server.getTextDocumentService().didOpen(new DidOpenTextDocumentParams(new TextDocumentItem(uri, "masl", 0, program)));
        await(published, uri, 0, 0);
        double open = (System.nanoTime() - start) / 1e6;

        double[] changes = new double[MEASURED_CHANGES];
        long cpu = 0;
        for (int version = 1; version <= WARM_UP_CHANGES + MEASURED_CHANGES; version++) {
            boolean breaking = version % 2 == 1;
            Range line = new Range(new Position(edited, 0), new Position(edited, lines.get(edited).length()));
            String text = breaking ? "  totl++;" : "  total++;";
            if (version == WARM_UP_CHANGES + 1) {
                cpu = Bench.processCpuNanos();
            }
            start = System.nanoTime();
            server.getTextDocumentService().didChange(new DidChangeTextDocumentParams(
                    new VersionedTextDocumentIdentifier(uri, version), List.of(new TextDocumentContentChangeEvent(line, text))));
            await(published, uri, version, breaking ? 1 : 0);
            lines = replaced(lines, edited, text);
            if (version > WARM_UP_CHANGES) {
                changes[version - WARM_UP_CHANGES - 1] = (System.nanoTime() - start) / 1e6;
            }
        }
        double cpuPerChange = (Bench.processCpuNanos() - cpu) / 1e6 / MEASURED_CHANGES;
        server.shutdown().get(60, TimeUnit.SECONDS);
        server.exit();
        serving.get(60, TimeUnit.SECONDS);
        // Closed at once: a piped stream whose writing thread has ended unclosed reports a broken pipe to its reader.
        fromServer.close();
        toServer.close();
        deleteQuietly(folder);
        return new Figures(changes, cpuPerChange, open);
    }

    private static List<String> replaced(List<String> lines, int index, String line) {
        String[] copy = lines.toArray(String[]::new);
        copy[index] = line;
        return Arrays.asList(copy);
    }

    private static void await(BlockingQueue<PublishDiagnosticsParams> published, String uri, int version, int errors)
            throws InterruptedException {
        while (true) {
            PublishDiagnosticsParams params = published.poll(60, TimeUnit.SECONDS);
            if (params == null) {
                throw new IllegalStateException("masl lsp published no diagnostics for version " + version);
            }
            if (params.getUri().equals(uri) && Integer.valueOf(version).equals(params.getVersion())) {
                if (params.getDiagnostics().size() != errors) {
                    throw new IllegalStateException("expected " + errors + " errors in version " + version + ", got "
                            + params.getDiagnostics());
                }
                return;
            }
        }
    }

    private static void deleteQuietly(Path folder) {
        try {
            Files.deleteIfExists(folder);
        } catch (IOException ignored) {
            // A temporary folder left behind is harmless.
        }
    }

    /** Keeps what the server publishes. */
    private record Client(BlockingQueue<PublishDiagnosticsParams> published) implements LanguageClient {
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
            System.out.println("   masl lsp: " + message.getMessage());
        }
    }
}
