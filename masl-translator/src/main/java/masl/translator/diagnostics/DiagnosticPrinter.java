package masl.translator.diagnostics;

import java.io.PrintStream;
import java.util.Map;

/**
 * Renders diagnostics as compilers do: the headline, the offending source line, and a caret under
 * the column. Source texts are given by file name; a diagnostic whose file is unknown, or whose
 * line lies outside it, is printed as its headline alone.
 */
public final class DiagnosticPrinter {

    private final Map<String, String> sources;

    public DiagnosticPrinter(Map<String, String> sourcesByFile) {
        this.sources = Map.copyOf(sourcesByFile);
    }

    public String render(Diagnostic diagnostic) {
        StringBuilder out = new StringBuilder(diagnostic.headline()).append('\n');
        String line = sourceLine(diagnostic);
        if (line != null) {
            out.append(line).append('\n');
            if (diagnostic.column() > 0) {
                out.append(caretLine(line, diagnostic.column())).append('\n');
            }
        }
        return out.toString();
    }

    public void print(Iterable<Diagnostic> diagnostics, PrintStream err) {
        int count = 0;
        for (Diagnostic diagnostic : diagnostics) {
            err.print(render(diagnostic));
            count++;
        }
        if (count > 0) {
            err.println(count + (count == 1 ? " error" : " errors"));
        }
    }

    private String sourceLine(Diagnostic diagnostic) {
        String text = sources.get(diagnostic.file());
        if (text == null || diagnostic.line() <= 0) {
            return null;
        }
        String[] lines = text.split("\r\n|\r|\n", -1);
        return diagnostic.line() <= lines.length ? lines[diagnostic.line() - 1] : null;
    }

    /** Tabs are kept so the caret lines up with the source line in a terminal. */
    private static String caretLine(String line, int column) {
        StringBuilder caret = new StringBuilder();
        for (int i = 0; i < column - 1; i++) {
            caret.append(i < line.length() && line.charAt(i) == '\t' ? '\t' : ' ');
        }
        return caret.append('^').toString();
    }
}
