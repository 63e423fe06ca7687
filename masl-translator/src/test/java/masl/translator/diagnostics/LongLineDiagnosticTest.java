package masl.translator.diagnostics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.DiagnosticPrinter;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Test;

/** A syntax error in a line too long for a terminal is shown by the part of the line around it. */
class LongLineDiagnosticTest {

    @Test
    void aSyntaxErrorInTheDeclarationOf100000AgentsPrintsAShortExcerptAtTheSlip() {
        String declaration = "Default " + names(0, 50_000) + " a50000, " + names(50_001, 100_000) + " = newAgent(Default);";
        String source = "import Default.xml as Default;\n" + declaration + "\nasynchronous entry main (true) { }\n";

        Translation translation = new Translator(AgentPath.parse("")).translate(SourceFile.of("many.masl", source));

        String report = new DiagnosticPrinter(Map.of("many.masl", source)).report(translation.diagnostics().sorted());
        List<String> shown = report.lines().toList();
        assertTrue(shown.get(0).startsWith("many.masl:2:"), report);
        assertTrue(report.length() < 1_000, "the report is " + report.length() + " characters long");
        assertEquals("a50000", shown.get(1).substring(caretAt(shown.get(2)), caretAt(shown.get(2)) + 6), report);
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
