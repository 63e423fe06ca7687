package masl.translator.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import masl.runtime.diagnostic.Diagnostic;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Test;

/** Syntax errors: one test per mistake a user makes, asserting the message, line and column. */
class SyntaxErrorTest {

    private static final String HEADER = "import Default.xml as Default;\nDefault a, b = newAgent(Default);\n";

    private static List<Diagnostic> errorsOf(String program) {
        Diagnostics diagnostics = new Diagnostics();
        ProgramParser.parse(SourceFile.of("p.masl", program), diagnostics);
        return diagnostics.sorted();
    }

    private static void assertSingleError(String program, int line, int column, String message) {
        assertEquals(List.of(Diagnostic.error("p.masl", line, column, message)), errorsOf(program));
    }

    @Test
    void missingSemicolonIsReportedAtTheEndOfTheStatement() {
        assertSingleError(HEADER + "asynchronous entry main (true) {\n  .log(\"x\")\n  a.nop();\n}\n",
                4, 12, "expected ';'");
    }

    @Test
    void missingClosingBraceAtEndOfFile() {
        assertSingleError(HEADER + "asynchronous entry main (true) {\n  .nop();\n",
                5, 1, "unexpected end of file");
    }

    @Test
    void blockWithoutMode() {
        assertSingleError(HEADER + "entry main (true) { .nop(); }\n",
                3, 1, "unexpected 'entry'");
    }

    @Test
    void entryWithoutTest() {
        assertSingleError(HEADER + "synchronous entry main { .nop(); }\n",
                3, 24, "unexpected '{', expected '('");
    }

    @Test
    void aSecondInitialValueInOneDeclaration() {
        assertSingleError(HEADER + "scalar entry main (true) {\n  local int i = 0, j = 1;\n  .logln(i);\n}\n",
                4, 18, "unexpected ',': a declaration's names come before its one initial value"
                        + " (`local int a, b = 0;`); give other values in declarations of their own");
    }

    @Test
    void aVariableOutsideEveryBlock() {
        assertSingleError(HEADER + "shared int x = 0;\nscalar entry main (true) {\n  .logln(x);\n}\n",
                3, 1, "unexpected 'shared': variables are declared at the head of an entry block, `shared` for one"
                        + " the block's members share: `synchronous entry main (true) { shared int x = 0; … }`");
    }

    @Test
    void unterminatedString() {
        assertEquals(Diagnostic.error("p.masl", 4, 8, "unterminated string literal"),
                errorsOf(HEADER + "scalar entry main (true) {\n  .log(\"hello);\n}\n").get(0));
    }

    @Test
    void characterOutsideTheLanguage() {
        assertSingleError(HEADER + "scalar entry main (true) {\n  .log(#1);\n}\n",
                4, 8, "unexpected character '#'");
    }

    @Test
    void newAgentWithoutParentheses() {
        assertSingleError("import Default.xml;\nDefault a = newAgent;\n",
                2, 21, "unexpected ';', expected '('");
    }

    @Test
    void declarationWithoutName() {
        assertSingleError(HEADER + "asynchronous entry main (true) {\n  local int = 3;\n}\n",
                4, 13, "unexpected '=', expected a name");
    }

    @Test
    void reactWithoutEvent() {
        assertSingleError(HEADER + "asynchronous entry main (true) {\n  react () { resume; }\n}\n",
                4, 10, "unexpected ')', expected 'default' or a name");
    }

    @Test
    void breakWithAnExpression() {
        assertSingleError(HEADER + "asynchronous entry main (true) {\n  break(1 + 1);\n}\n",
                4, 11, "unexpected '+', expected ')'");
    }

    @Test
    void twoTopLevelBlocks() {
        assertSingleError(HEADER + "scalar entry main (true) { .nop(); }\nscalar entry second (true) { .nop(); }\n",
                4, 1, "unexpected 'scalar', expected end of file");
    }

    @Test
    void everySyntaxErrorOfAFileIsReported() {
        List<Diagnostic> errors = errorsOf(HEADER
                + "asynchronous entry main (true) {\n"
                + "  .log(\"a\")\n"
                + "  b.nop();\n"
                + "  local int = 3;\n"
                + "  .log(#);\n"
                + "}\n");
        assertEquals(List.of(
                Diagnostic.error("p.masl", 4, 12, "expected ';'"),
                Diagnostic.error("p.masl", 6, 13, "unexpected '=', expected a name"),
                Diagnostic.error("p.masl", 7, 8, "unexpected character '#'")), errors);
    }
}
