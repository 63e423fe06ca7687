package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The cases of {@code resume}: numbering, sharing and jumps to points placed later. */
class CaseWriterTest {

    @Test
    void pointsAreNumberedInTheOrderTheyArePlacedAndJumpsForwardResolve() {
        CaseWriter cases = new CaseWriter();
        CaseWriter.Point start = cases.point();
        CaseWriter.Point later = cases.point();
        cases.place(start, "t.masl:1: start");
        cases.jumpLine("if (x) { ", later, " }");
        cases.suspending("ctx.stepBoundary()", cases.point());
        cases.line("work();");
        cases.place(later, "t.masl:3: later");
        cases.end("return;");
        assertEquals(List.of(
                "case 0: // t.masl:1: start",
                "    if (x) { pc = 2; continue; }",
                "    pc = 1;",
                "    if (!ctx.stepBoundary()) return;",
                "case 1:",
                "    work();",
                "case 2: // t.masl:3: later",
                "    return;"), lines(cases));
    }

    @Test
    void pointsPlacedWithNoCodeBetweenShareACaseAndItsFirstComment() {
        CaseWriter cases = new CaseWriter();
        CaseWriter.Point first = cases.point();
        CaseWriter.Point second = cases.point();
        cases.place(first, null);
        cases.place(second, "t.masl:2: named by the second");
        cases.jump(first);
        assertEquals(List.of("case 0: // t.masl:2: named by the second", "    pc = 0;", "    continue;"),
                lines(cases));
    }

    @Test
    void codeAfterAJumpStartsACaseOfItsOwnSoJavaAcceptsIt() {
        CaseWriter cases = new CaseWriter();
        CaseWriter.Point start = cases.point();
        cases.place(start, "t.masl:1: break");
        cases.jump(start);
        cases.line("never();");
        assertEquals(List.of("case 0: // t.masl:1: break", "    pc = 0;", "    continue;", "case 1:", "    never();"),
                lines(cases));
    }

    private static List<String> lines(CaseWriter cases) {
        JavaLines out = new JavaLines(100);
        cases.number();
        cases.render(out, "");
        return List.of(out.toString().split("\n"));
    }

    @Test
    void aPointCannotBePlacedInsideAJavaBlock() {
        CaseWriter cases = new CaseWriter();
        cases.place(cases.point(), null);
        cases.open("if (x) {");
        assertThrows(IllegalStateException.class, () -> cases.place(cases.point(), null));
    }
}
