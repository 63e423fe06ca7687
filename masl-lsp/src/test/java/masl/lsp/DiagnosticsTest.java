package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import masl.runtime.descriptor.AgentPath;
import masl.translator.Frontend;
import masl.translator.source.SourceFile;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.Range;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Diagnostics: the front end's, placed where the editor underlines them, for the program and
 * for the descriptors it imports, and cleared when they are gone.
 */
class DiagnosticsTest {

    @TempDir
    Path folder;

    private final Editor editor = new Editor();

    @AfterEach
    void close() {
        editor.close();
    }

    @Test
    void anErrorUnderlinesTheWordItIsAbout() throws Exception {
        String program = "import Default.xml;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) {\n  .logln(undeclared);\n}\n";
        editor.open(program);
        Diagnostic only = single(editor.diagnostics(editor.uri));
        assertEquals(new Range(new Position(3, 9), new Position(3, 19)), only.getRange());
        assertEquals(DiagnosticSeverity.Error, only.getSeverity());
        assertEquals("masl", only.getSource());
    }

    @Test
    void columnsAfterACharacterOutsideTheBasicPlaneAreCountedAsTheEditorCounts() throws Exception {
        // MASL counts code points, LSP UTF-16 units: the emoji is one of the first and two of the second.
        String program = "import Default.xml;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) {\n  .logln(\"\uD83D\uDE00\" + undeclared);\n}\n";
        editor.open(program);
        Diagnostic only = single(editor.diagnostics(editor.uri));
        String line = program.split("\n")[3];
        assertEquals(new Position(3, line.indexOf("undeclared")), only.getRange().getStart());
        int frontEndColumn = new Frontend(AgentPath.parse("")).analyse(SourceFile.of("p.masl", program))
                .diagnostics().sorted().get(0).column();
        assertEquals(line.codePointCount(0, line.indexOf("undeclared")) + 1, frontEndColumn, "the front end counts code points");
    }

    @Test
    void aDescriptorsErrorsAreShownInTheDescriptorAndClearedWhenFixed() throws Exception {
        Path descriptor = folder.resolve("Broken.xml");
        String broken = """
                <?xml version="1.0" encoding="UTF-8"?>
                <Agent short_class_name="Broken" full_class_name="masl.agents.Default" target_language="java">
                  <Permeability permeability_name="odd" umask="000">
                    <Member member_id="X9" rights="111"/>
                  </Permeability>
                </Agent>
                """;
        Files.writeString(descriptor, broken);
        Path program = folder.resolve("p.masl");
        String text = "import Broken.xml;\nBroken a = newAgent(Broken);\n";
        Files.writeString(program, text);
        editor.open(program.toUri().toString(), text);

        String descriptorUri = descriptor.toUri().toString();
        Diagnostic inDescriptor = single(editor.diagnostics(descriptorUri));
        assertEquals(3, inDescriptor.getRange().getStart().getLine(), inDescriptor.toString());
        assertEquals(new Position(3, 4), inDescriptor.getRange().getStart());
        assertEquals("descriptor Broken.xml has errors", single(editor.diagnostics(editor.uri)).getMessage());

        Files.writeString(descriptor, broken.replace("    <Member member_id=\"X9\" rights=\"111\"/>\n", ""));
        editor.server.getWorkspaceService().didChangeWatchedFiles(new org.eclipse.lsp4j.DidChangeWatchedFilesParams(
                List.of(new org.eclipse.lsp4j.FileEvent(descriptorUri, org.eclipse.lsp4j.FileChangeType.Changed))));
        assertEquals(List.of(), editor.diagnostics(editor.uri).getDiagnostics());
        assertEquals(List.of(), editor.diagnostics(descriptorUri).getDiagnostics());
    }

    @Test
    void closingAProgramClearsItsDiagnostics() throws Exception {
        editor.open("import Default.xml;\nDefault a = newAgent(Nobody);\n");
        assertEquals(1, editor.diagnostics(editor.uri).getDiagnostics().size());
        editor.server.getTextDocumentService().didClose(new org.eclipse.lsp4j.DidCloseTextDocumentParams(
                new org.eclipse.lsp4j.TextDocumentIdentifier(editor.uri)));
        assertEquals(List.of(), editor.diagnostics(editor.uri).getDiagnostics());
    }

    private static Diagnostic single(PublishDiagnosticsParams params) {
        assertEquals(1, params.getDiagnostics().size(), params.toString());
        return params.getDiagnostics().get(0);
    }
}
