package masl.translator.diagnostics;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

/**
 * Renders diagnostics as compilers do: the headline, the offending source line, and a caret under
 * the column. Source texts come from the map given, else from the file of that name (a descriptor);
 * a diagnostic whose text cannot be had, or whose line lies outside it, is printed as its headline alone.
 */
public final class DiagnosticPrinter {

    private final Map<String, String> sources;

    public DiagnosticPrinter(Map<String, String> sourcesByFile) {
        this.sources = new HashMap<>(sourcesByFile);
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

    /** What {@link #print} writes, as text: for callers that report through an exception. */
    public String report(Iterable<Diagnostic> diagnostics) {
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        print(diagnostics, new PrintStream(text, true, StandardCharsets.UTF_8));
        return text.toString(StandardCharsets.UTF_8);
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
        String text = sources.computeIfAbsent(diagnostic.file(), DiagnosticPrinter::readOrNull);
        if (text == null || diagnostic.line() <= 0) {
            return null;
        }
        String[] lines = text.split("\r\n|\r|\n", -1);
        return diagnostic.line() <= lines.length ? lines[diagnostic.line() - 1] : null;
    }

    private static String readOrNull(String file) {
        try {
            return Files.readString(Path.of(file), StandardCharsets.UTF_8);
        } catch (IOException | InvalidPathException | SecurityException unreadable) {
            return null;
        }
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
