package masl.runtime.diagnostic;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The one form every input's problems are shown in, and the one order they are listed in. */
class DiagnosticTest {

    @Test
    void theHeadlineLeavesOutAPositionThatIsNotKnown() {
        assertEquals("a.masl:3:7: error: no", Diagnostic.error("a.masl", 3, 7, "no").headline());
        assertEquals("a.xml:3: error: no", Diagnostic.error("a.xml", 3, 0, "no").headline());
        assertEquals("a.xml: error: no", Diagnostic.error("a.xml", 0, 0, "no").headline());
        assertEquals("w.xode:1:2: warning: odd", new Diagnostic("w.xode", 1, 2, Severity.WARNING, "odd").toString());
    }

    /** A command-line option's value is one line: its column is named as such, not as a file's line 1. */
    @Test
    void anOptionsValueIsPositionedByItsColumnAlone() {
        assertEquals("--place a=c2,b: column 6: error: expected AGENT=CONTAINER",
                Diagnostic.inOption("--place", "a=c2,b", 6, "expected AGENT=CONTAINER").headline());
    }

    @Test
    void diagnosticsSortByFileThenLineThenColumn() {
        Diagnostic b = Diagnostic.error("b.masl", 1, 1, "b");
        Diagnostic a2 = new Diagnostic("a.masl", 2, 1, Severity.WARNING, "a2");
        Diagnostic a10 = Diagnostic.error("a.masl", 10, 1, "a10");
        Diagnostic a2x9 = Diagnostic.error("a.masl", 2, 9, "a2x9");
        List<Diagnostic> listed = new ArrayList<>(List.of(b, a10, a2x9, a2));

        Collections.sort(listed);

        assertEquals(List.of(a2, a2x9, a10, b), listed);
    }
}
