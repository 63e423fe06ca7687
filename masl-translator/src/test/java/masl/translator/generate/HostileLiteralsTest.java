package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.scheduling.SeededScheduler;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The Java that runs is the Java the checker accepted: random string and character literals over a
 * hostile alphabet (quotes, backslashes, {@code u}, hexadecimal digits, line breaks, {@code *}{@code /},
 * control and non-ASCII characters, surrogates, and runs of them that look like escapes), each
 * written in MASL source with escapes chosen at random among those Java reads the same way, are
 * translated, compiled and run: the journal holds exactly the values drawn. Each statement's source
 * also lands in a generated comment, which must stay a comment. A Unicode escape standing for the
 * literal's own syntax, anywhere among such characters, is refused at its column.
 */
@Tag("slow")
class HostileLiteralsTest {

    private static final long[] SEEDS = {1, 2, 3, 4, 5, 6, 7, 8};
    private static final int STRINGS = 30;
    private static final int CHARACTERS = 15;
    private static final String HEADER = "import Default.xml;\nDefault a = newAgent(Default);\nscalar entry main (true) {\n";

    /** What values are drawn from: characters, and runs that meet Java's escapes and comments head-on. */
    private static final String[] UNITS = {"\"", "'", "\\", "\\", "u", "uu", "U", "0", "2", "7", "8", "a", "A", "c",
        "D", "f", "\n", "\r", "\t", "\b", "\f", "*", "/", "*/", "/*", "//", ";", " ", "(", ")", "}", "\0", "\u001a",
        "\u007f", "\u0085", "\u00e9", "\u2028", "\uFEFF", "\uD83D\uDE00", "\uD800", "\uDC00", "\\u0022", "\\u000a",
        "u000a", "\\\\u005c", "x"};

    @Test
    void randomHostileLiteralsRunAsTheirValues() {
        for (long seed : SEEDS) {
            Random random = new Random(seed);
            StringBuilder program = new StringBuilder(HEADER);
            StringBuilder expected = new StringBuilder();
            for (int i = 0; i < STRINGS; i++) {
                String value = value(random);
                program.append("  .logln(").append(literal(value, '"', random)).append(");\n");
                expected.append(value).append('\n');
            }
            for (int i = 0; i < CHARACTERS; i++) {
                char value = character(random);
                program.append("  .logln(\"\" + ").append(literal(String.valueOf(value), '\'', random)).append(");\n");
                expected.append(value).append('\n');
            }
            program.append("}\n");
            String journal = Programs.journal(Programs.load(program.toString()), new SeededScheduler(seed));
            assertEquals(expected.toString(), journal, "seed " + seed + ", program:\n" + program);
        }
    }

    @Test
    void aUnicodeEscapeOfTheLiteralsSyntaxIsRefusedWhereverItStands() {
        String[] refused = {"0022", "005c", "005C", "000a", "000A", "000d", "000D"};
        for (long seed : SEEDS) {
            Random random = new Random(seed);
            for (int i = 0; i < 20; i++) {
                String before = literal(value(random), '"', random);
                String escape = "\\" + "u".repeat(1 + random.nextInt(3)) + refused[random.nextInt(refused.length)];
                String after = literal(value(random), '"', random);
                String literal = before.substring(0, before.length() - 1) + escape + after.substring(1);
                Translation translation = Programs.translate("test.masl", HEADER + "  .logln(" + literal + ");\n}\n");
                List<Diagnostic> errors = translation.diagnostics().sorted();
                int column = "  .logln(".length() + before.codePointCount(0, before.length() - 1) + 1;
                assertEquals(1, errors.size(), () -> "seed " + seed + ": " + literal + " gave " + errors);
                assertEquals(4, errors.get(0).line(), literal);
                assertEquals(column, errors.get(0).column(), () -> literal + ": " + errors.get(0));
                assertTrue(errors.get(0).message().startsWith(escape + " is "), errors.get(0).message());
            }
        }
    }

    /**
     * The second program: {@code \\u000a} in a string, defused into {@code \\\u000a} in the
     * case's comment, ended the comment and ran the rest of the line as Java.
     */
    @Test
    void anEscapedBackslashBeforeULeavesTheGeneratedCommentAComment() {
        String value = "\\u000a if (true) throw new IllegalStateException(); //";
        assertEquals(value + "\n", Programs.journal(Programs.load(HEADER + "  .logln(\"\\\\u000a if (true) throw new"
                + " IllegalStateException(); //\");\n}\n"), new SeededScheduler(1)));
    }

    /** A file name is written into comments as well: one holding a Unicode escape stays a comment there. */
    @Test
    void aFileNameHoldingAUnicodeEscapeLeavesTheGeneratedCommentsComments() {
        String name = "x\\u000aif (true) throw new IllegalStateException(); *\\u002f.masl";
        Translation translation = new Translator(AgentPath.parse("")).translate(
                new SourceFile(name, Programs.FIXTURES, HEADER + "  .logln(\"ok\");\n}\n"));
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        assertEquals("ok\n", Programs.journal(MissionLoader.load(translation, AgentPath.parse("")),
                new SeededScheduler(1)));
    }

    /** A value of up to 12 units. */
    private static String value(Random random) {
        StringBuilder value = new StringBuilder();
        int units = random.nextInt(13);
        for (int i = 0; i < units; i++) {
            value.append(UNITS[random.nextInt(UNITS.length)]);
        }
        return value.length() == 0 && random.nextBoolean() ? "\"" : value.toString();
    }

    /** The first char of a value (a lone surrogate, maybe). */
    private static char character(Random random) {
        String value = "";
        while (value.isEmpty()) {
            value = value(random);
        }
        return value.charAt(0);
    }

    /** {@code value} as a MASL literal between {@code quote}s, each character written one of the ways Java reads as it. */
    private static String literal(String value, char quote, Random random) {
        StringBuilder source = new StringBuilder().append(quote);
        for (int i = 0; i < value.length(); i++) {
            char c = value.charAt(i);
            char next = i + 1 < value.length() ? value.charAt(i + 1) : quote;
            if (Character.isHighSurrogate(c) && Character.isLowSurrogate(next) && random.nextBoolean()) {
                source.append(c).append(next);
                i++;
                continue;
            }
            List<String> ways = new ArrayList<>();
            boolean syntax = c == quote || c == '\\' || c == '\n' || c == '\r';
            if (!syntax && !Character.isSurrogate(c)) {
                ways.add(String.valueOf(c));
            }
            String simple = switch (c) {
                case '"' -> "\\\"";
                case '\'' -> "\\'";
                case '\\' -> "\\\\";
                case '\n' -> "\\n";
                case '\r' -> "\\r";
                case '\t' -> "\\t";
                case '\b' -> "\\b";
                case '\f' -> "\\f";
                default -> null;
            };
            if (simple != null) {
                ways.add(simple);
            }
            if (c <= 0377) {
                // Java's octal escapes take up to three digits: a shorter one must not meet a digit.
                String octal = Integer.toOctalString(c);
                ways.add("\\" + (next >= '0' && next <= '7' ? "0".repeat(3 - octal.length()) + octal : octal));
            }
            if (!syntax) {
                String hex = String.format("%04x", (int) c);
                ways.add("\\" + "u".repeat(1 + random.nextInt(3)) + (random.nextBoolean() ? hex : hex.toUpperCase()));
            }
            source.append(ways.get(random.nextInt(ways.size())));
        }
        return source.append(quote).toString();
    }
}
