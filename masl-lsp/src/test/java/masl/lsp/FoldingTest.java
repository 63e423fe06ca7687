package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.eclipse.lsp4j.FoldingRange;
import org.eclipse.lsp4j.FoldingRangeRequestParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Folding on blocks, whatever the indentation. */
class FoldingTest {

    private final Editor editor = new Editor();

    @AfterEach
    void close() {
        editor.close();
    }

    @Test
    void bracesSpanningLinesAndLongCommentsFold() {
        editor.open("""
                /* two
                   lines */
                import Default.xml;
                Default a = newAgent(Default);
                asynchronous entry main (true) {
                scalar entry one (true) {
                .nop();
                }
                react (timeout) { resume; }
                }
                """);
        List<FoldingRange> ranges = editor.server.getTextDocumentService()
                .foldingRange(new FoldingRangeRequestParams(new TextDocumentIdentifier(editor.uri))).join();
        assertEquals(List.of("0-1 comment", "5-6 null", "4-8 null"), ranges.stream()
                .map(range -> range.getStartLine() + "-" + range.getEndLine() + " " + range.getKind()).toList());
    }
}
