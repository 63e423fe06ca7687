package masl.translator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.sun.management.ThreadMXBean;
import java.lang.management.ManagementFactory;
import java.util.List;
import java.util.function.Function;
import java.util.function.IntFunction;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Programs of a size users write when they declare a large team, checked and translated whole, and
 * the work of checking and translating linear in the size of the program, counted as the bytes the
 * translating thread allocates: a count that other jobs on the machine do not change, unlike time.
 * Doubling the input may not allocate more than {@value #MOST_FOR_TWICE_THE_INPUT} times as much
 * (linear work allocates twice as much; work that copies or rebuilds what it has seen for each
 * new element, four times).
 *
 * <p>A search that only scans (no allocation) grows the time, not the bytes: checking once
 * compared each agent's name with every agent before it, and 100,000 agents took 100 s to check.
 * {@link #aDeclarationLineOfManyAgentsIsCheckedAndTranslated} checks {@value #LARGE_TEAM} agents,
 * a few seconds of work when linear and minutes when quadratic: past the class's time limit, which
 * fails the test once the work ends (translation cannot be interrupted halfway).
 * How long checking and translating take, and how that grows with the input, is measured by
 * {@code gradle bench} (docs/performance.md, section 4), never asserted here.
 */
@Timeout(120)
@Tag("slow")
class TranslationScaleTest {

    private static final int LARGE_TEAM = 200_000;
    private static final double MOST_FOR_TWICE_THE_INPUT = 2.5;
    private static final ThreadMXBean THREADS = (ThreadMXBean) ManagementFactory.getThreadMXBean();

    @Test
    void aDeclarationLineOfManyAgentsIsCheckedAndTranslated() {
        String program = team(LARGE_TEAM);
        Translation translation = new Translator(AgentPath.parse("")).translate(SourceFile.of("team.masl", program));
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        String last = "a" + (LARGE_TEAM - 1);
        assertTrue(translation.javaSources().values().stream().anyMatch(java -> java.contains("a0.." + last)),
                "every agent of the line, a0 to " + last + ", is in the generated program");

        // The same name again at the end of the line: found, at its position.
        String twice = program.replace(" = newAgent", ", a7 = newAgent");
        List<Diagnostic> errors = new Frontend(AgentPath.parse("")).analyse(SourceFile.of("team.masl", twice))
                .diagnostics().sorted();
        int column = twice.lines().toList().get(1).indexOf(", a7 = newAgent") + 3;
        assertEquals(List.of("team.masl:2:" + column + ": error: agent a7 is already declared"),
                errors.stream().map(Diagnostic::headline).toList());
    }

    @Test
    void checkingAllocatesInProportionToTheNumberOfAgents() {
        assertLinear(allocatedBy(this::check), TranslationScaleTest::team, 20_000);
    }

    @Test
    void translatingAllocatesInProportionToTheNumberOfAgents() {
        assertLinear(allocatedBy(this::translate), TranslationScaleTest::team, 20_000);
    }

    @Test
    void checkingAllocatesInProportionToTheNumberOfStatements() {
        assertLinear(allocatedBy(this::check), TranslationScaleTest::statements, 4_000);
    }

    @Test
    void translatingAllocatesInProportionToTheNumberOfStatements() {
        assertLinear(allocatedBy(this::translate), TranslationScaleTest::statements, 4_000);
    }

    private boolean check(SourceFile source) {
        return new Frontend(AgentPath.parse("")).analyseHere(source).succeeded();
    }

    private boolean translate(SourceFile source) {
        return new Translator(AgentPath.parse("")).translateOnThisThread(source).succeeded();
    }

    private interface Step {
        boolean run(SourceFile source);
    }

    /**
     * The bytes {@code step} allocates on the thread that runs it, a thread with the stack translation
     * is given; fails if the step fails.
     */
    private static Function<SourceFile, Long> allocatedBy(Step step) {
        return source -> DeepStack.call("scale", () -> {
            long before = THREADS.getCurrentThreadAllocatedBytes();
            assertTrue(step.run(source), "the program does not translate");
            return THREADS.getCurrentThreadAllocatedBytes() - before;
        });
    }

    /**
     * Twice the input allocates at most {@value #MOST_FOR_TWICE_THE_INPUT} times as much, after a
     * warm-up: the interpreter allocates what the compiled code keeps in registers.
     */
    private static void assertLinear(Function<SourceFile, Long> allocated, IntFunction<String> program, int size) {
        SourceFile small = SourceFile.of("scale.masl", program.apply(size));
        SourceFile large = SourceFile.of("scale.masl", program.apply(2 * size));
        allocated.apply(small);
        long smallBytes = allocated.apply(small);
        long largeBytes = allocated.apply(large);
        double ratio = (double) largeBytes / smallBytes;
        assertTrue(ratio <= MOST_FOR_TWICE_THE_INPUT, String.format("%d took %d bytes, twice as much %d bytes (%.2f times)",
                size, smallBytes, largeBytes, ratio));
    }

    /** {@code agents} Default agents and a one-statement program. */
    private static String team(int agents) {
        StringBuilder text = new StringBuilder("import Default.xml as Default;\nDefault a0");
        for (int i = 1; i < agents; i++) {
            text.append(", a").append(i);
        }
        return text.append(" = newAgent(Default);\nscalar entry main (true) { .logln(\"done\"); }\n").toString();
    }

    /** Two agents and a program of about {@code count} declarations and statements of several kinds. */
    private static String statements(int count) {
        StringBuilder text = new StringBuilder("import Default.xml as Default;\nDefault a, b = newAgent(Default);\n"
                + "asynchronous entry main (true) {\n  shared int total = 0;\n");
        for (int i = 0; i < count / 4; i++) {
            text.append("  local int v").append(i).append(" = ").append(i).append(";\n");
        }
        for (int i = 0; i < count / 4; i++) {
            text.append("  total += v").append(i).append(";\n")
                    .append("  if (total > ").append(i).append(") .logln(\"s").append(i).append("\"); else .nop();\n")
                    .append("  scalar entry b").append(i).append(" (true) { b.nop(); }\n");
        }
        return text.append("}\n").toString();
    }
}
