package masl.translator;

import static masl.translator.FrontendErrors.errorsOf;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * Every mistake of a file in one run, each reported once where it is, and nothing reported that is
 * only a consequence of another: files with several independent mistakes of one kind, and of several
 * kinds, checked for their exact list of errors as {@code masl check} prints them.
 */
class EveryErrorInOneRunTest {

    @Test
    void missingSemicolons() {
        assertEquals("""
                p.masl:5:14: error: expected ';'
                p.masl:7:14: error: expected ';'
                p.masl:9:14: error: expected ';'
                p.masl:12:20: error: expected ';'""", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    .log("a")
                    .logln("b");
                    x = x + 1
                    a.nop();
                    .logln(x)
                    x++;
                    if (x > 0) {
                        .logln("c")
                    }
                }
                """));
    }

    @Test
    void aMissingSemicolonBeforeAnAttributeIsNotAMissingMember() {
        assertEquals("p.masl:5:11: error: expected ';'", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    .nop()
                    .x = 3;
                }
                """));
    }

    @Test
    void aMissingSemicolonBeforeAPrimitiveIsNotAMethodOfTheValueBefore() {
        assertEquals("""
                p.masl:5:16: error: expected ';'
                p.masl:8:10: error: cannot find method lenght() in String""", errorsOf("""
                asynchronous entry main (true) {
                    local String s = "x";
                    s = s + "y"
                    .logln(s);
                    s.trim()
                        .lenght();
                }
                """));
    }

    @Test
    void missingClosingParentheses() {
        assertEquals("""
                p.masl:5:13: error: expected ')'
                p.masl:6:25: error: expected ')'
                p.masl:7:14: error: expected ')'
                p.masl:10:19: error: expected ')'""", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    .log("a";
                    .logln(.getProxyID();
                    if (x > 0 {
                        x++;
                    }
                    while ((x < 3) {
                        x++;
                    }
                    .logln(x);
                }
                """));
    }

    @Test
    void missingClosingBracesAreReportedWhereTheIndentationEndsTheirBlocks() {
        assertEquals("""
                p.masl:6:13: error: expected '}' to close the '{' of line 5
                p.masl:11:16: error: expected '}' to close the '{' of line 10""", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    if (x > 0) {
                        x++;
                    while (x < 3) {
                        x++;
                    }
                    synchronous entry inner (true) {
                        .nop();
                    .logln(x);
                }
                """));
    }

    @Test
    void anExtraClosingBraceIsTheOneAfterWhichItsBlockGoesOn() {
        assertEquals("""
                p.masl:8:5: error: unexpected '}': no block ends here
                p.masl:10:12: error: expected ';'""", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    if (x > 0) {
                        x++;
                    }
                    }
                    while (x < 3) {
                        x++
                    }
                }
                """));
    }

    @Test
    void misspeltKeywords() {
        assertEquals("""
                p.masl:4:5: error: unknown keyword locl; did you mean `local`?
                p.masl:5:5: error: unknown keyword shard; did you mean `shared`?
                p.masl:6:5: error: unknown keyword Slabel; did you mean `SLabel`?
                p.masl:7:5: error: unknown mode synchronus; did you mean `synchronous`?
                p.masl:10:5: error: unknown keyword whle; did you mean `while`?
                p.masl:13:5: error: cannot find symbol fi; did you mean `if`?
                p.masl:14:5: error: not a statement: brek; did you mean `break;`?""", errorsOf("""
                asynchronous entry main (true) {
                    locl int x = 0;
                    shard String s = "s";
                    Slabel l;
                    synchronus entry inner (true) {
                        .nop();
                    }
                    whle (x < 3) {
                        x++;
                    }
                    fi (x > 3) .logln(s);
                    brek;
                }
                """));
    }

    @Test
    void strayTokens() {
        assertEquals("""
                p.masl:5:15: error: unexpected ';'
                p.masl:6:15: error: unexpected ')', expected ';'
                p.masl:7:9: error: unexpected ']', expected ';'
                p.masl:8:5: error: unexpected character '#'""", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    x = x + + ;
                    .logln(x) );
                    x++ ]
                    # .logln(x);
                }
                """));
    }

    @Test
    void syntaxErrorsRepairedAsMeantLeaveTheOtherErrorsOfTheFileReported() {
        assertEquals("""
                p.masl:5:14: error: expected ';'
                p.masl:6:5: error: unknown keyword whle; did you mean `while`?
                p.masl:7:9: error: cannot find symbol y; did you mean `x`?
                p.masl:9:7: error: cannot find primitive logn in any imported agent type; did you mean `logln`?""",
                errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    x = x + 1
                    whle (x < 3) {
                        y++;
                    }
                    a.logn(x);
                }
                """));
    }

    @Test
    void afterAGuessNothingIsReportedThatCouldBeItsConsequence() {
        // The brace placed by the indentation is a guess: the undeclared y is not reported with it.
        assertEquals("p.masl:6:13: error: expected '}' to close the '{' of line 5", errorsOf("""
                asynchronous entry main (true) {
                    local int x = 0;
                    if (x > 0) {
                        x++;
                    y++;
                }
                """));
    }
}
