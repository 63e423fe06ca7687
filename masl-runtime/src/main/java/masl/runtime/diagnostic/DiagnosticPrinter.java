package masl.runtime.diagnostic;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.EnumMap;
import java.util.HashMap;
import java.util.Map;
import java.util.stream.Collectors;

/**
 * Renders diagnostics as compilers do: the headline, the offending source line, and a caret under
 * the column. Source texts come from the map given, else from the file of that name (a descriptor);
 * a diagnostic whose text cannot be had, or whose line lies outside it, is printed as its headline alone.
 *
 * <p>A line longer than {@value #WIDTH} characters is shown as the {@value #WIDTH} around the column,
 * with {@code ...} where it was cut: the declaration of 100,000 agents is one line of 700 KB, and a
 * terminal shows nothing useful of it whole.
 */
public final class DiagnosticPrinter {

    /** The most characters of a source line shown. */
    static final int WIDTH = 120;
    private static final String CUT = "...";

    private final Map<String, String> sources;
    /** Each file's lines, split once: a program with many errors is not split once per error. */
    private final Map<String, String[]> lines = new HashMap<>();

    public DiagnosticPrinter(Map<String, String> sourcesByFile) {
        this.sources = new HashMap<>(sourcesByFile);
    }

    public String render(Diagnostic diagnostic) {
        StringBuilder out = new StringBuilder(diagnostic.headline()).append('\n');
        String line = sourceLine(diagnostic);
        if (line != null) {
            Excerpt excerpt = Excerpt.of(line, diagnostic.column());
            out.append(excerpt.text()).append('\n');
            if (diagnostic.column() > 0) {
                out.append(caretLine(excerpt.text(), excerpt.column())).append('\n');
            }
        }
        return out.toString();
    }

    /** What is shown of a line, and the column within it that the caret marks. */
    private record Excerpt(String text, int column) {
        static Excerpt of(String line, int column) {
            if (line.length() <= WIDTH) {
                return new Excerpt(line, column);
            }
            int at = Math.min(Math.max(column - 1, 0), line.length());
            int start = Math.max(0, Math.min(at - WIDTH / 2, line.length() - WIDTH));
            int end = start + WIDTH;
            // Not between the two halves of a surrogate pair: half a character prints as '?'.
            if (start > 0 && Character.isLowSurrogate(line.charAt(start))) {
                start--;
            }
            if (end < line.length() && Character.isLowSurrogate(line.charAt(end))) {
                end++;
            }
            String before = start > 0 ? CUT : "";
            String after = end < line.length() ? CUT : "";
            return new Excerpt(before + line.substring(start, end) + after, column - start + before.length());
        }
    }

    /** What {@link #print} writes, as text: for callers that report through an exception. */
    public String report(Iterable<Diagnostic> diagnostics) {
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        print(diagnostics, new PrintStream(text, true, StandardCharsets.UTF_8));
        return text.toString(StandardCharsets.UTF_8);
    }

    /** Each diagnostic rendered, then how many errors and warnings there were ({@code 2 errors, 1 warning}). */
    public void print(Iterable<Diagnostic> diagnostics, PrintStream err) {
        Map<Severity, Integer> counts = new EnumMap<>(Severity.class);
        for (Diagnostic diagnostic : diagnostics) {
            err.print(render(diagnostic));
            counts.merge(diagnostic.severity(), 1, Integer::sum);
        }
        if (!counts.isEmpty()) {
            err.println(counts.entrySet().stream().map(count -> count.getValue() + " " + count.getKey().word()
                    + (count.getValue() == 1 ? "" : "s")).collect(Collectors.joining(", ")));
        }
    }

    private String sourceLine(Diagnostic diagnostic) {
        String text = sources.computeIfAbsent(diagnostic.file(), DiagnosticPrinter::readOrNull);
        if (text == null || diagnostic.line() <= 0) {
            return null;
        }
        String[] fileLines = lines.computeIfAbsent(diagnostic.file(), file -> text.split("\r\n|\r|\n", -1));
        return diagnostic.line() <= fileLines.length ? fileLines[diagnostic.line() - 1] : null;
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
