package masl.lsp;

import java.net.URI;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import masl.translator.source.SourceFile;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;

/**
 * One version of an open document and the conversions between the two ways of counting columns: LSP's
 * (0-based lines, UTF-16 code units) and MASL's diagnostics and ANTLR's tokens (1-based lines, code points).
 * The two agree except after a character outside the Basic Multilingual Plane. Immutable.
 */
final class TextDocument {

    private final String uri;
    private final int version;
    private final String text;
    /** UTF-16 offset of the start of each line. */
    private final int[] lineStarts;

    TextDocument(String uri, int version, String text) {
        this.uri = uri;
        this.version = version;
        this.text = text;
        this.lineStarts = lineStarts(text);
    }

    String uri() {
        return uri;
    }

    int version() {
        return version;
    }

    String text() {
        return text;
    }

    /** The file of a {@code file:} document, else null (an unsaved buffer). */
    Path file() {
        try {
            URI parsed = URI.create(uri);
            return "file".equals(parsed.getScheme()) ? Path.of(parsed) : null;
        } catch (IllegalArgumentException | java.nio.file.FileSystemNotFoundException notAFile) {
            return null;
        }
    }

    /**
     * The program as the translator reads it: named by its path, as {@code masl check FILE} names it when
     * given an absolute path, and with descriptors looked up next to it.
     */
    SourceFile source() {
        Path file = file();
        if (file == null) {
            return SourceFile.of(uri, text);
        }
        return new SourceFile(file.toString(), file.toAbsolutePath().getParent(), text);
    }

    /** The document after the client's edits, in order; a change without range replaces the whole text. */
    TextDocument edited(int newVersion, List<TextDocumentContentChangeEvent> changes) {
        TextDocument current = this;
        for (TextDocumentContentChangeEvent change : changes) {
            String newText;
            if (change.getRange() == null) {
                newText = change.getText();
            } else {
                int start = current.offset(change.getRange().getStart());
                int end = Math.max(start, current.offset(change.getRange().getEnd()));
                newText = current.text.substring(0, start) + change.getText() + current.text.substring(end);
            }
            current = new TextDocument(uri, newVersion, newText);
        }
        return new TextDocument(uri, newVersion, current.text);
    }

    /** The text of a 0-based line, without its line break; empty outside the document. */
    String line(int line) {
        if (line < 0 || line >= lineStarts.length) {
            return "";
        }
        int end = line + 1 < lineStarts.length ? lineStarts[line + 1] : text.length();
        while (end > lineStarts[line] && (text.charAt(end - 1) == '\n' || text.charAt(end - 1) == '\r')) {
            end--;
        }
        return text.substring(lineStarts[line], end);
    }

    /** UTF-16 offset of an LSP position, clamped to the document. */
    int offset(Position position) {
        int line = position.getLine();
        if (line < 0) {
            return 0;
        }
        if (line >= lineStarts.length) {
            return text.length();
        }
        return lineStarts[line] + Math.min(Math.max(position.getCharacter(), 0), line(line).length());
    }

    /** The LSP position of a UTF-16 offset. */
    Position position(int offset) {
        int clamped = Math.max(0, Math.min(offset, text.length()));
        int line = Arrays.binarySearch(lineStarts, clamped);
        if (line < 0) {
            line = -line - 2;
        }
        return new Position(line, clamped - lineStarts[line]);
    }

    /** Code point index (ANTLR's {@code Token.getStartIndex()}) of a UTF-16 offset. */
    int codePointIndex(int offset) {
        return text.codePointCount(0, Math.max(0, Math.min(offset, text.length())));
    }

    /** UTF-16 offset of a code point index. */
    int offsetOfCodePoint(int codePointIndex) {
        try {
            return text.offsetByCodePoints(0, codePointIndex);
        } catch (IndexOutOfBoundsException pastTheEnd) {
            return text.length();
        }
    }

    /**
     * The LSP position of a 1-based line and a 0-based column counted in code points, as ANTLR's tokens
     * give them; a column past the end of the line stays there (a missing ';' is reported after the line).
     */
    Position positionOf(int line1, int codePointColumn) {
        String lineText = line(line1 - 1);
        int utf16 = 0;
        int column = 0;
        while (column < codePointColumn && utf16 < lineText.length()) {
            utf16 += Character.charCount(lineText.codePointAt(utf16));
            column++;
        }
        return new Position(Math.max(0, line1 - 1), utf16 + (codePointColumn - column));
    }

    private static int[] lineStarts(String text) {
        int[] starts = new int[16];
        int count = 0;
        starts[count++] = 0;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            boolean lineBreak = c == '\n' || c == '\r' && (i + 1 == text.length() || text.charAt(i + 1) != '\n');
            if (lineBreak) {
                if (count == starts.length) {
                    starts = Arrays.copyOf(starts, count * 2);
                }
                starts[count++] = i + 1;
            }
        }
        return Arrays.copyOf(starts, count);
    }
}
