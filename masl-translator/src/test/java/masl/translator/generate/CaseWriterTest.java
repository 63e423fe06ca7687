package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
        cases.endWithReturn();
        assertEquals(List.of(
                "case 0: // t.masl:1: start",
                "    if (x) { pc = 2; continue; }",
                "    pc = 1;",
                "    if (!ctx.stepBoundary()) return;",
                "case 1:",
                "    work();",
                "    pc = 2;",
                "case 2: // t.masl:3: later",
                "    return;"), lines(cases));
    }

    @Test
    void aStatementAfterCodeOfAnotherStartsACaseThatPcNamesWhenFallenInto() {
        CaseWriter cases = new CaseWriter();
        cases.place(cases.point(), "t.masl:1: declarations of main");
        cases.line("x = 0;");
        cases.statementOwnCase();
        cases.note("t.masl:2: y = 1 / x;");
        cases.line("y = 1 / x;");
        assertEquals(List.of(
                "case 0: // t.masl:1: declarations of main",
                "    x = 0;",
                "    pc = 1;",
                "case 1: // t.masl:2: y = 1 / x;",
                "    y = 1 / x;"), lines(cases));
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

    @Test
    void aLongRunOfStatementsIsCutIntoCasesWhereAStatementStarts() {
        CaseWriter cases = new CaseWriter();
        cases.place(cases.point(), "t.masl:1: declarations of main");
        String declaration = "main$v = 1;";
        int perCase = CaseWriter.LONGEST_CASE / (declaration.length() + 1) + 1;
        for (int i = 0; i < 3 * perCase; i++) {
            cases.statementStart();
            cases.line(declaration);
        }
        cases.number();
        assertEquals(3, cases.cases().size());
        assertEquals("t.masl:1: declarations of main", cases.cases().get(1).callSource());
        assertTrue(cases.cases().get(0).fallsThrough());
    }

    @Test
    void aStatementInsideAJavaBlockIsNeverCutFromIt() {
        CaseWriter cases = new CaseWriter();
        cases.place(cases.point(), "t.masl:1: if (x)");
        cases.open("if (x) {");
        for (int i = 0; i < CaseWriter.LONGEST_CASE; i++) {
            cases.statementStart();
            cases.line("ctx.clearEvents();");
        }
        cases.close("}");
        cases.number();
        assertEquals(1, cases.cases().size());
    }

    @Test
    void aPartOfASplitMachineSetsPcThroughTheProgramAndReturnsFalseWhenTheAgentStopped() {
        CaseWriter cases = new CaseWriter();
        cases.place(cases.point(), "t.masl:1: .nop();");
        cases.suspending("ctx.stepBoundary()", cases.point());
        cases.endWithReturn();
        cases.number();
        StringBuilder text = new StringBuilder();
        cases.cases().forEach(c -> CaseWriter.render(text, c, "", true));
        assertEquals(List.of("case 0: // t.masl:1: .nop();", "    setPc(1);", "    if (!ctx.stepBoundary()) return false;",
                "case 1:", "    return false;"), List.of(text.toString().split("\n")));
        assertFalse(cases.cases().get(1).fallsThrough());
    }

    private static List<String> lines(CaseWriter cases) {
        StringBuilder text = new StringBuilder();
        cases.number();
        cases.cases().forEach(c -> CaseWriter.render(text, c, "", false));
        return List.of(text.toString().split("\n"));
    }

    @Test
    void aPointCannotBePlacedInsideAJavaBlock() {
        CaseWriter cases = new CaseWriter();
        cases.place(cases.point(), null);
        cases.open("if (x) {");
        assertThrows(IllegalStateException.class, () -> cases.place(cases.point(), null));
    }
}
