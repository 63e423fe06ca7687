package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.scheduling.SeededScheduler;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.parse.Nesting;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Deep nesting translates, compiles and runs, whatever the caller's stack (2,000 levels of
 * brackets, blocks or operators overflowed the stack, an internal error); past masl's limit it is a
 * positioned error naming the limit.
 */
@Tag("slow")
class DeepNestingTest {

    private static final int LEVELS = 2_000;

    @Test
    @Timeout(300)
    void twoThousandLevelsOfEachConstructRunOnAnOrdinaryStack() throws InterruptedException {
        String program = "import Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) {\n"
                + "  local int x = " + "(".repeat(LEVELS) + "1" + ")".repeat(LEVELS) + ";\n"
                + "  local int y = " + IntStream.range(0, LEVELS).mapToObj(i -> "x").collect(Collectors.joining(" + ")) + ";\n"
                + "  local boolean z = " + "!".repeat(LEVELS) + "true;\n"
                + "  " + "{".repeat(LEVELS) + ".logln(x + \" \" + y + \" \" + z);" + "}".repeat(LEVELS) + "\n"
                + "  " + IntStream.range(0, LEVELS).mapToObj(i -> "if (y == " + i + ") { .logln(" + i + "); }")
                        .collect(Collectors.joining(" else ")) + " else { .logln(\"none\"); }\n"
                + "  " + "if (x > 0) ".repeat(LEVELS) + ".logln(\"ifs\");\n"
                + IntStream.range(0, LEVELS).mapToObj(i -> "  scalar entry b" + i + " (true) {\n")
                        .collect(Collectors.joining())
                + "  .logln(\"inner\");\n" + "  }\n".repeat(LEVELS)
                + "}\n";
        // A thread with a stack as small as a default one: the translator and javac must not depend on it.
        AtomicReference<Object> result = new AtomicReference<>();
        Thread small = new Thread(null, () -> {
            try {
                Translation translation = Programs.translate("deep.masl", program);
                assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
                result.set(MissionLoader.load(translation, AgentPath.parse("")));
            } catch (Throwable failure) {
                result.set(failure);
            }
        }, "small stack", 512 * 1024);
        small.start();
        small.join();
        if (result.get() instanceof Throwable failure) {
            throw new AssertionError("translating or compiling failed", failure);
        }
        assertEquals("1 2000 true\nnone\nifs\ninner\n",
                Programs.journal((MissionLoader) result.get(), new SeededScheduler(1)));
    }

    @Test
    void nestingPastTheLimitIsAPositionedErrorNamingIt() {
        String brackets = "(".repeat(Nesting.DEEPEST) + "(1" + ")".repeat(Nesting.DEEPEST + 1);
        Translation translation = Programs.translate("deeper.masl", "import Default.xml as Default;\n"
                + "Default a = newAgent(Default);\nscalar entry main (true) {\n  .logln(" + brackets + ");\n}\n");
        List<String> errors = translation.diagnostics().sorted().stream().map(Diagnostic::headline).toList();
        assertEquals(1, errors.size(), errors::toString);
        Matcher error = Pattern.compile("deeper\\.masl:4:(\\d+): error: the program nests too deeply here: masl"
                + " translates at most 10,000 levels of brackets, operators and statements within statements")
                .matcher(errors.get(0));
        assertTrue(error.matches(), errors.get(0));
        // At one of the brackets, a few levels before the last: the block and the call are levels too.
        int column = Integer.parseInt(error.group(1));
        assertTrue(column > Nesting.DEEPEST - 10 && column <= "  .logln(".length() + Nesting.DEEPEST, errors.get(0));
    }

    /** What a stack overflow the measure did not foresee is reported as: the program's most deeply nested token. */
    @Test
    void anOverflowIsReportedAtTheMostDeeplyNestedToken() {
        Diagnostics diagnostics = new Diagnostics();
        Nesting.reportTooDeep(SourceFile.of("overflow.masl", "x = 1;\ny = a + (b + (c - d) * e);\nz = 2;\n"),
                diagnostics);
        assertEquals("overflow.masl:2:17: error: the program nests too deeply here: masl translates at most 10,000"
                + " levels of brackets, operators and statements within statements",
                diagnostics.sorted().get(0).headline());
    }
}
