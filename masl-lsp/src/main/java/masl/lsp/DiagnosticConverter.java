package masl.lsp;

import masl.runtime.diagnostic.Diagnostic;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;

/**
 * Turns a front-end {@link Diagnostic} into an LSP one: the message unchanged, the start at the diagnostic's
 * line and column, and the end at the end of the word there so that the editor underlines it. A diagnostic
 * for a whole line underlines the line; one for a whole file, its first line.
 */
final class DiagnosticConverter {

    static final String SOURCE = "masl";

    private DiagnosticConverter() {
    }

    static org.eclipse.lsp4j.Diagnostic convert(Diagnostic diagnostic, TextDocument text) {
        return new org.eclipse.lsp4j.Diagnostic(range(diagnostic, text), diagnostic.message(),
                DiagnosticSeverity.Error, SOURCE);
    }

    static Range range(Diagnostic diagnostic, TextDocument text) {
        int line = Math.max(diagnostic.line(), 1);
        String lineText = text.line(line - 1);
        if (diagnostic.line() <= 0 || diagnostic.column() <= 0) {
            return new Range(new Position(line - 1, 0), new Position(line - 1, lineText.length()));
        }
        Position start = text.positionOf(line, diagnostic.column() - 1);
        return new Range(start, new Position(start.getLine(), wordEnd(lineText, start.getCharacter())));
    }

    /**
     * Where the word starting at {@code start} ends: a name, a number, a quoted string or an XML element
     * name ({@code <Primitive}); a single character otherwise, nothing past the end of the line.
     */
    static int wordEnd(String line, int start) {
        if (start >= line.length()) {
            return start;
        }
        char first = line.charAt(start);
        int end = start + 1;
        if (first == '"' || first == '\'') {
            while (end < line.length() && line.charAt(end) != first) {
                end += line.charAt(end) == '\\' ? 2 : 1;
            }
            return Math.min(end + 1, line.length());
        }
        boolean number = Character.isDigit(first);
        if (first == '<' || number || Character.isJavaIdentifierStart(first)) {
            while (end < line.length()
                    && (Character.isJavaIdentifierPart(line.charAt(end)) || number && line.charAt(end) == '.')) {
                end++;
            }
        }
        return end;
    }
}
