package masl.lsp;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.translator.Translator;
import masl.translator.source.SourceFile;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.services.LanguageClient;

/**
 * Checks open programs as {@code masl check} does and publishes what it reports: the program's diagnostics on
 * the program, a descriptor's on the descriptor's file. {@code masl check} translates the program
 * ({@link Translator#translate}: parse, analysis, generation, which refuses the constructs it cannot
 * translate yet) and prints the translation's diagnostics; then it compiles the generated Java, whose
 * failure is a bug of masl reported as an internal error, never a diagnostic: the editor leaves that step out. Checks run one at a time on
 * a thread of their own, so that typing is never held up by them; a check whose document has changed
 * again since it was asked for is skipped, the newer one being queued behind it.
 *
 * <p>A descriptor shared by several open programs shows the union of what their checks found in it; its
 * diagnostics are cleared when no check finds any more.
 */
final class DiagnosticsPublisher implements AutoCloseable {

    private final Supplier<AgentPath> agentPath;
    private final Supplier<LanguageClient> client;
    private final ExecutorService checks = Executors.newSingleThreadExecutor(runnable -> {
        Thread thread = new Thread(runnable, "masl-lsp-check");
        thread.setDaemon(true);
        return thread;
    });
    /** The latest version of each open program; checks of older versions are skipped. */
    private final Map<String, Integer> latest = new ConcurrentHashMap<>();
    /** Descriptor URI -> program URI -> what the program's last check found in that descriptor. */
    private final Map<String, Map<String, List<org.eclipse.lsp4j.Diagnostic>>> descriptorFindings = new HashMap<>();

    DiagnosticsPublisher(Supplier<AgentPath> agentPath, Supplier<LanguageClient> client) {
        this.agentPath = agentPath;
        this.client = client;
    }

    /** Queues a check of this version of the document. */
    void check(TextDocument document) {
        latest.put(document.uri(), document.version());
        checks.execute(() -> {
            if (latest.getOrDefault(document.uri(), Integer.MIN_VALUE) == document.version()) {
                publish(document);
            }
        });
    }

    /** Clears the diagnostics of a program that was closed, and its findings in descriptors. */
    void closed(String uri) {
        latest.remove(uri);
        checks.execute(() -> {
            client.get().publishDiagnostics(new PublishDiagnosticsParams(uri, List.of()));
            updateDescriptors(uri, Map.of());
        });
    }

    private void publish(TextDocument document) {
        SourceFile source = document.source();
        List<Diagnostic> found;
        try {
            found = new Translator(agentPath.get()).translate(source).diagnostics().sorted();
        } catch (RuntimeException | StackOverflowError bug) {
            client.get().logMessage(new MessageParams(MessageType.Error,
                    "masl: internal error while checking " + source.name() + ", please report it: " + bug));
            return;
        }
        List<org.eclipse.lsp4j.Diagnostic> own = new ArrayList<>();
        Map<String, List<org.eclipse.lsp4j.Diagnostic>> inDescriptors = new LinkedHashMap<>();
        Map<String, TextDocument> descriptorTexts = new HashMap<>();
        for (Diagnostic diagnostic : found) {
            if (diagnostic.file().equals(source.name())) {
                own.add(DiagnosticConverter.convert(diagnostic, document));
                continue;
            }
            TextDocument descriptor = descriptorTexts.computeIfAbsent(diagnostic.file(), DiagnosticsPublisher::readFile);
            if (descriptor != null) {
                inDescriptors.computeIfAbsent(descriptor.uri(), uri -> new ArrayList<>())
                        .add(DiagnosticConverter.convert(diagnostic, descriptor));
            }
        }
        PublishDiagnosticsParams params = new PublishDiagnosticsParams(document.uri(), own);
        params.setVersion(document.version());
        client.get().publishDiagnostics(params);
        updateDescriptors(document.uri(), inDescriptors);
    }

    /**
     * A descriptor as a document, when it is a file: errors in a shipped descriptor (inside a jar) have no
     * file to show them in, and the import that names it reports them already.
     */
    private static TextDocument readFile(String name) {
        try {
            Path file = Path.of(name).toAbsolutePath();
            return new TextDocument(file.toUri().toString(), 0, Files.readString(file, StandardCharsets.UTF_8));
        } catch (IOException | InvalidPathException | SecurityException notAFile) {
            return null;
        }
    }

    private void updateDescriptors(String programUri, Map<String, List<org.eclipse.lsp4j.Diagnostic>> findings) {
        LinkedHashSet<String> touched = new LinkedHashSet<>(findings.keySet());
        descriptorFindings.forEach((descriptorUri, byProgram) -> {
            if (byProgram.remove(programUri) != null) {
                touched.add(descriptorUri);
            }
        });
        findings.forEach((descriptorUri, diagnostics) ->
                descriptorFindings.computeIfAbsent(descriptorUri, uri -> new HashMap<>()).put(programUri, diagnostics));
        for (String descriptorUri : touched) {
            LinkedHashSet<org.eclipse.lsp4j.Diagnostic> union = new LinkedHashSet<>();
            descriptorFindings.getOrDefault(descriptorUri, Map.of()).values().forEach(union::addAll);
            if (union.isEmpty()) {
                descriptorFindings.remove(descriptorUri);
            }
            client.get().publishDiagnostics(new PublishDiagnosticsParams(descriptorUri, new ArrayList<>(union)));
        }
    }

    @Override
    public void close() {
        checks.shutdownNow();
        try {
            checks.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
        }
    }
}
