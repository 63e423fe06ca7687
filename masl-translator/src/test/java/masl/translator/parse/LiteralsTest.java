package masl.translator.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import masl.runtime.diagnostic.Diagnostic;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Test;

/**
 * String and character literals decoded as javac decodes them, and the Unicode escapes javac would
 * read as the literal's own syntax refused at their position (the random round trip through javac is
 * {@code generate.HostileLiteralsTest}).
 */
class LiteralsTest {

    private static final String HEADER = "import Default.xml as Default;\nDefault a = newAgent(Default);\n";

    @Test
    void escapesAsJavaReadsThem() throws Exception {
        assertEquals("a\"b\\c\nd\te\rf\bg\fh'", Literals.string("\"a\\\"b\\\\c\\nd\\te\\rf\\bg\\fh\\'\""));
        assertEquals("\u00e9\u20ac\uD83D\uDE00", Literals.string("\"\\u00e9\\uuu20AC\\ud83d\\uDE00\""));
        assertEquals("\\u0041", Literals.string("\"\\\\u0041\""), "an escaped backslash starts no Unicode escape");
        assertEquals("\\A", Literals.string("\"\\\\\\u0041\""), "the third backslash does");
    }

    @Test
    void octalEscapesTakeAsManyDigitsAsJavaDoes() throws Exception {
        assertEquals("\u00ff", Literals.string("\"\\377\""));
        assertEquals("?7", Literals.string("\"\\777\""), "\\77 then 7: three digits only from 0 to 3");
        assertEquals("\u0007" + "8", Literals.string("\"\\78\""));
        assertEquals("\u00018", Literals.string("\"\\18\""));
        assertEquals("\u0000", Literals.string("\"\\0\""));
        assertEquals("S4", Literals.string("\"\\1234\""));
    }

    @Test
    void characters() throws Exception {
        assertEquals('"', Literals.character("'\\u0022'"), "a quote is no end of a character literal");
        assertEquals('\'', Literals.character("'\\''"));
        assertEquals('\uD800', Literals.character("'\\uD800'"), "a lone surrogate is one char");
        Literals.Problem two = assertThrows(Literals.Problem.class, () -> Literals.character("'\uD83D\uDE00'"));
        assertEquals("a character literal holds one UTF-16 char; '\uD83D\uDE00' holds 2: write it as a String",
                two.getMessage());
    }

    @Test
    void unicodeEscapesOfTheLiteralsOwnSyntaxAreRefusedWhereTheyStand() {
        assertProblem("\"a\\u0022); System.exit(5); //\"", 2,
                "\\u0022 is \", which Java reads as the end of the string: write \\\"");
        assertProblem("\"x\\u000a\"", 2, "\\u000a is a line break, which ends the line in Java before the string is"
                + " read: write \\n");
        assertProblem("\"\\uu000D\"", 1, "\\uu000D is a line break, which ends the line in Java before the string is"
                + " read: write \\r");
        assertProblem("\"\\u005c\"", 1, "\\u005c is a backslash, which Java reads as the start of an escape sequence:"
                + " write \\\\");
        assertProblem("\"\\u12g4\"", 1, "illegal Unicode escape: \\u must be followed by four hexadecimal digits");
        assertProblem("\"\\u\uFF10\uFF10\uFF14\uFF11\"", 1,
                "illegal Unicode escape: \\u must be followed by four hexadecimal digits");
        Literals.Problem quote = assertThrows(Literals.Problem.class, () -> Literals.character("'\\u0027'"));
        assertEquals("\\u0027 is ', which Java reads as the end of the character literal: write \\'",
                quote.getMessage());
    }

    /** The program: {@code masl check} refuses it, at the escape, instead of letting {@code System.exit} run. */
    @Test
    void aStringEndedByAUnicodeEscapeIsAPositionedError() {
        Diagnostics diagnostics = new Diagnostics();
        ProgramParser.parse(SourceFile.of("p.masl", HEADER
                + "scalar entry main (true) {\n  .logln(\"a\\u0022); System.exit(5); //\");\n  .logln('\\u0027');\n}\n"),
                diagnostics);
        assertEquals(List.of(
                Diagnostic.error("p.masl", 4, 12, "\\u0022 is \", which Java reads as the end of the string: write \\\""),
                Diagnostic.error("p.masl", 5, 11,
                        "\\u0027 is ', which Java reads as the end of the character literal: write \\'")),
                diagnostics.sorted());
    }

    @Test
    void columnsCountCharactersAsTheEditorShowsThem() {
        Diagnostics diagnostics = new Diagnostics();
        ProgramParser.parse(SourceFile.of("p.masl", HEADER
                + "scalar entry main (true) {\n  .logln(\"\uD83D\uDE00\\u000a\");\n}\n"), diagnostics);
        assertEquals(List.of(Diagnostic.error("p.masl", 4, 12, "\\u000a is a line break, which ends the line in Java"
                + " before the string is read: write \\n")), diagnostics.sorted());
    }

    private static void assertProblem(String literal, int offset, String message) {
        Literals.Problem problem = assertThrows(Literals.Problem.class, () -> Literals.string(literal));
        assertEquals(message, problem.getMessage());
        assertEquals(offset, problem.offset());
    }
}
