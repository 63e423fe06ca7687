package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.junit.jupiter.api.Test;

/** The editor's incremental edits and the two ways of counting columns. */
class TextDocumentTest {

    @Test
    void incrementalEditsApplyInOrder() {
        TextDocument document = new TextDocument("file:///p.masl", 1, "ab\ncd\r\nef");
        TextDocument edited = document.edited(2, List.of(
                new TextDocumentContentChangeEvent(new Range(new Position(1, 1), new Position(2, 1)), "X"),
                new TextDocumentContentChangeEvent(new Range(new Position(0, 0), new Position(0, 0)), "// ")));
        assertEquals("// ab\ncXf", edited.text());
        assertEquals(2, edited.version());
        assertEquals("new", document.edited(3, List.of(new TextDocumentContentChangeEvent("new"))).text());
    }

    @Test
    void linesEndWithAnyOfTheThreeLineBreaks() {
        TextDocument document = new TextDocument("file:///p.masl", 1, "a\nbb\r\nccc\rd");
        assertEquals(List.of("a", "bb", "ccc", "d"), List.of(document.line(0), document.line(1), document.line(2),
                document.line(3)));
        assertEquals(new Position(2, 1), document.position(document.offset(new Position(2, 1))));
    }

    @Test
    void codePointColumnsBecomeUtf16Columns() {
        TextDocument document = new TextDocument("file:///p.masl", 1, "x\n\uD83D\uDE00 = y;");
        assertEquals(new Position(1, 3), document.positionOf(2, 2));
        assertEquals(3, document.codePointIndex(document.offset(new Position(1, 2))));
    }
}
