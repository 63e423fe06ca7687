package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.stream.Collectors;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.scheduling.SeededScheduler;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * What Java cannot hold is a positioned error of the program, never javac's error on the generated
 * code (each was once an internal error, exit 70): a number literal out of range, a string
 * constant over 65,535 bytes, a statement over the 64 KB of a method; and MASL names that are the
 * generated code's own names are renamed, not clashed with.
 */
@Tag("slow")
class JavaLimitsTest {

    private static final String HEADER = "import Default.xml as Default;\nDefault a = newAgent(Default);\n";

    @Test
    void numberLiteralsOutOfRangeArePositionedErrors() {
        List<String> errors = errors("""
                scalar entry main (true) {
                  local int tooLarge = 2147483648;
                  local long tooLong = 9223372036854775808L;
                  local int notOctal = 09;
                  local double huge = 1e400;
                  local float tiny = 1e-50f;
                  local int wide = 0x1_0000_0000;
                  local int subtracted = 0 - 2147483648;
                }
                """);
        assertEquals(List.of(
                "limits.masl:4:24: error: integer number too large for an int: at most 2147483647; write 2147483648L"
                        + " for a long",
                "limits.masl:5:24: error: integer number too large for a long: at most 9223372036854775807",
                "limits.masl:6:24: error: 09 is not a number: one that starts with 0 is octal, with the digits 0 to 7",
                "limits.masl:7:23: error: floating-point number too large for a double",
                "limits.masl:8:22: error: floating-point number too small for a float: it would be 0",
                "limits.masl:9:20: error: integer number too large for an int: at most 32 bits; write 0x1_0000_0000L"
                        + " for a long",
                "limits.masl:10:30: error: integer number too large for an int: at most 2147483647; write 2147483648L"
                        + " for a long"), errors);
    }

    @Test
    void theExtremeLiteralsJavaAcceptsRunWithTheirValues() {
        assertEquals("-2147483648 -9223372036854775808 -1 -1 8 2\n", journal("""
                scalar entry main (true) {
                  local int smallest = -2147483648;
                  local long smallestLong = -9223372036854775808L;
                  local int allBits = 0xFFFF_FFFF;
                  local int octal = 037777777777;
                  .logln(smallest + " " + smallestLong + " " + allBits + " " + octal + " " + 010 + " " + 0b10);
                  while (true) { exit(0x1); }
                  break(0_1);
                }
                """));
    }

    @Test
    void aStringConstantOverJavasLimitIsAPositionedError() {
        String long40k = "a".repeat(40_000);
        List<String> errors = errors("scalar entry main (true) {\n"
                + "  .logln(\"" + "é".repeat(33_000) + "\");\n"
                + "  .logln(\"" + long40k + "\" + \"" + long40k + "\");\n"
                + "  .logln(\"" + long40k + "\" + .getProxyID() + \"" + long40k + "\");\n"
                + "}\n");
        assertEquals(List.of(
                "limits.masl:4:10: error: a string constant of 66,000 bytes (in UTF-8): Java holds at most 65,535 in"
                        + " one; build a longer text at run time",
                "limits.masl:5:10: error: a string constant of 80,000 bytes (in UTF-8): Java holds at most 65,535 in"
                        + " one; build a longer text at run time"), errors);
    }

    /** Java counts U+1F600 as 6 bytes, UTF-8 as 4: the message gives the size a user can check, and Java's. */
    @Test
    void aStringBeyondTheBasicPlaneIsMeasuredInUtf8AndInJavasCount() {
        List<String> errors = errors("scalar entry main (true) {\n  .logln(\"" + "\uD83D\uDE00".repeat(12_000) + "\");\n}\n");
        assertEquals(List.of("limits.masl:4:10: error: a string constant of 48,000 bytes (in UTF-8), 72,000 in Java's class"
                + " files (6 bytes for a character beyond U+FFFF, 2 for U+0000): Java holds at most 65,535 in one; build a"
                + " longer text at run time"), errors);
    }

    @Test
    void aStatementTooLargeForAJavaMethodIsAPositionedError() {
        String sum = java.util.stream.IntStream.range(0, 9_000).mapToObj(i -> "x[0]").collect(Collectors.joining("+"));
        List<String> errors = errors("scalar entry main (true) {\n  local int[] x = new int[1];\n  .logln(" + sum + ");\n}\n");
        assertEquals(List.of("limits.masl:5:3: error: this statement is too large for Java, which holds at most 64 KB"
                + " of bytecode in a method: split it into several statements"), errors);
    }

    /** Before, {@code type Agent} made {@code AgentProgram extends AgentProgram}, and a block {@code uri} hid {@code URI}. */
    @Test
    void maslNamesThatAreTheGeneratedCodesOwnAreRenamed() {
        String program = """
                import Default.xml as Mission;
                type Agent use Default.xml;
                Agent a = newAgent(Agent);
                Mission m = newAgent(Mission);
                scalar entry main (true) {
                  scalar entry uri (true) { .logln("uri"); }
                  scalar entry agents (true) { .logln("agents"); }
                  scalar entry keep (true) {
                    local int work = 1;
                    scalar entry work (true) {
                      local int n = 0;
                      n++;
                      if (n > 1) reelect(work);
                    }
                    .logln("keep " + work);
                  }
                  scalar entry a$b (true) { local int c = 1; .logln("a$b " + c); }
                  scalar entry a (true) { local int b$c = 2; .logln("a " + b$c); }
                }
                """;
        Translation translation = Programs.translate("names.masl", program);
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        assertEquals("uri\nagents\nkeep 1\na$b 1\na 2\n",
                Programs.journal(MissionLoader.load(translation, AgentPath.parse("")), new SeededScheduler(3)));
    }

    private static List<String> errors(String blocks) {
        Translation translation = Programs.translate("limits.masl", HEADER + blocks);
        return translation.diagnostics().sorted().stream().map(Diagnostic::headline).toList();
    }

    private static String journal(String blocks) {
        Translation translation = Programs.translate("limits.masl", HEADER + blocks);
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        return Programs.journal(MissionLoader.load(translation, AgentPath.parse("")), new SeededScheduler(1));
    }
}
