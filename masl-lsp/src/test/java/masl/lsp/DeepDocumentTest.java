package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.eclipse.lsp4j.FoldingRange;
import org.eclipse.lsp4j.FoldingRangeRequestParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.junit.jupiter.api.Test;

/**
 * A program nested deeper than masl translates ({@code masl check} refuses it at its first token too
 * deep) is answered all the same: it has no parse tree, so its outline and hover are empty, while
 * folding, read from its braces, still folds its block; nothing is an internal error.
 */
class DeepDocumentTest {

    private static final int LEVELS = 10_001;

    @Test
    void aProgramNestedTooDeeplyIsAnsweredWithoutAnInternalError() throws Exception {
        String program = "import Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) {\n  local int x = 0;\n  x‸ = " + "(".repeat(LEVELS) + "1" + ")".repeat(LEVELS) + ";\n}\n";
        try (Editor editor = new Editor().open(program)) {
            String problem = editor.diagnostics(editor.uri).getDiagnostics().get(0).getMessage();
            assertTrue(problem.contains("nest"), problem);

            assertEquals(List.of(), editor.symbols());
            List<FoldingRange> folding = editor.server.getTextDocumentService()
                    .foldingRange(new FoldingRangeRequestParams(new TextDocumentIdentifier(editor.uri))).get(60, TimeUnit.SECONDS);
            assertEquals(List.of(2), folding.stream().map(FoldingRange::getStartLine).toList(), "the block main folds");
            assertNull(editor.hover());
            assertEquals("", editor.log(), "nothing logged to the editor");
        }
    }
}
