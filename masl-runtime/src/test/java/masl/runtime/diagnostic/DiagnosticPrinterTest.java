package masl.runtime.diagnostic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;

/**
 * What {@code masl check} prints under each error's headline: the source line and a caret under the
 * column, the line cut to the part around the column when it is too long for a terminal.
 */
class DiagnosticPrinterTest {

    @Test
    void aShortLineIsShownWholeWithTheCaretUnderTheColumn() {
        String rendered = render("x.masl", "a\n\tlocal int i = ;\n", Diagnostic.error("x.masl", 2, 16, "an expression is missing"));

        assertEquals("x.masl:2:16: error: an expression is missing\n"
                + "\tlocal int i = ;\n"
                + "\t              ^\n", rendered);
    }

    @Test
    void aLongLineIsCutAroundTheColumnAndTheCaretStillMarksIt() {
        String line = names(0, 20_000);
        int column = line.indexOf("a12345,") + 1;

        List<String> shown = render("x.masl", line + "\n", Diagnostic.error("x.masl", 1, column, "no such agent")).lines().toList();

        String excerpt = shown.get(1);
        assertTrue(excerpt.startsWith("...") && excerpt.endsWith("..."), excerpt);
        assertEquals(DiagnosticPrinter.WIDTH + 6, excerpt.length());
        assertTrue(line.contains(excerpt.substring(3, excerpt.length() - 3)), "an unbroken part of the line");
        assertEquals("a12345,", excerpt.substring(caretAt(shown.get(2)), caretAt(shown.get(2)) + 7));
    }

    @Test
    void nearEitherEndOfALongLineOnlyTheOtherEndIsCut() {
        String line = names(0, 1_000);

        List<String> atStart = render("x.masl", line, Diagnostic.error("x.masl", 1, 4, "here")).lines().toList();
        List<String> atEnd = render("x.masl", line, Diagnostic.error("x.masl", 1, line.length(), "here")).lines().toList();

        assertEquals(line.substring(0, DiagnosticPrinter.WIDTH) + "...", atStart.get(1));
        assertEquals(3, caretAt(atStart.get(2)));
        assertEquals("..." + line.substring(line.length() - DiagnosticPrinter.WIDTH), atEnd.get(1));
        assertEquals(atEnd.get(1).length() - 1, caretAt(atEnd.get(2)));
    }

    @Test
    void theSummaryCountsErrorsAndWarningsApart() {
        String report = new DiagnosticPrinter(Map.of()).report(List.of(Diagnostic.error("<none>", 0, 0, "one"),
                new Diagnostic("<none>", 0, 0, Severity.WARNING, "two"), Diagnostic.error("<none>", 0, 0, "three")));

        assertEquals("<none>: error: one\n<none>: warning: two\n<none>: error: three\n2 errors, 1 warning\n", report);
    }

    private static String render(String file, String text, Diagnostic diagnostic) {
        return new DiagnosticPrinter(Map.of(file, text)).render(diagnostic);
    }

    /** {@code aFROM, ..., aTO-1}, a comma after each but the last. */
    private static String names(int from, int to) {
        return IntStream.range(from, to).mapToObj(i -> "a" + i).collect(Collectors.joining(", "));
    }

    private static int caretAt(String caretLine) {
        assertTrue(caretLine.endsWith("^") && caretLine.strip().equals("^"), caretLine);
        return caretLine.length() - 1;
    }
}
