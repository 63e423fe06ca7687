package masl.translator;

import static org.junit.jupiter.api.Assertions.assertTrue;

import com.sun.management.OperatingSystemMXBean;
import java.lang.management.ManagementFactory;
import java.util.function.IntFunction;
import masl.runtime.descriptor.AgentPath;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Checking and translating take time linear in the size of the program ({@code masl check}
 * of 100,000 agents took 100 s, of 12,500 agents 1.1 s). Doubling the input may not more than triple
 * the time. Each size is measured several times, interleaved with the other, after a warm-up, and
 * the least CPU time of each is compared: CPU time, not elapsed time, because other jobs on a loaded
 * machine lengthen the second without adding to the first.
 * The sizes take a good part of a second each, so that a collection or a compilation of the JIT does
 * not weigh as much as the work measured: 50,000 agents took some 70 ms to check, which one
 * collection on a loaded machine could triple; 400,000 take most of a second.
 */
@Timeout(300)
@Tag("slow")
class TranslationScaleTest {

    private static final int WARM_UPS = 1;
    private static final int MEASUREMENTS = 4;
    private static final double MOST_FOR_TWICE_THE_INPUT = 3.0;
    private static final OperatingSystemMXBean PROCESS =
            (OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();

    @Test
    void checkingIsLinearInTheNumberOfAgents() {
        assertLinear("checking", this::check, TranslationScaleTest::team, 400_000);
    }

    @Test
    void translatingIsLinearInTheNumberOfAgents() {
        assertLinear("translating", this::translate, TranslationScaleTest::team, 400_000);
    }

    @Test
    void checkingIsLinearInTheNumberOfStatements() {
        assertLinear("checking", this::check, TranslationScaleTest::statements, 16_000);
    }

    @Test
    void translatingIsLinearInTheNumberOfStatements() {
        assertLinear("translating", this::translate, TranslationScaleTest::statements, 8_000);
    }

    private boolean check(SourceFile source) {
        return new Frontend(AgentPath.parse("")).analyse(source).succeeded();
    }

    private boolean translate(SourceFile source) {
        return new Translator(AgentPath.parse("")).translate(source).succeeded();
    }

    private interface Step {
        boolean run(SourceFile source);
    }

    private static void assertLinear(String what, Step step, IntFunction<String> program, int size) {
        SourceFile small = SourceFile.of("scale.masl", program.apply(size));
        SourceFile large = SourceFile.of("scale.masl", program.apply(2 * size));
        for (int i = 0; i < WARM_UPS; i++) {
            assertTrue(step.run(small), what + " failed");
            assertTrue(step.run(large), what + " failed");
        }
        long bestSmall = Long.MAX_VALUE;
        long bestLarge = Long.MAX_VALUE;
        for (int i = 0; i < MEASUREMENTS; i++) {
            bestSmall = Math.min(bestSmall, timed(step, small));
            bestLarge = Math.min(bestLarge, timed(step, large));
        }
        double ratio = (double) bestLarge / bestSmall;
        String report = String.format("%s %d took %d ms of CPU, twice as much %d ms (%.1f times)", what, size,
                bestSmall / 1_000_000, bestLarge / 1_000_000, ratio);
        assertTrue(ratio <= MOST_FOR_TWICE_THE_INPUT, report);
    }

    /**
     * The CPU time of this JVM's threads while {@code step} runs: the work done, which other jobs on
     * the machine do not lengthen as they lengthen elapsed time (translation runs on a thread of its
     * own, with a deep stack, so the calling thread's time would not see it).
     */
    private static long timed(Step step, SourceFile source) {
        // The garbage of the previous measurement is not this one's to collect.
        System.gc();
        long start = PROCESS.getProcessCpuTime();
        step.run(source);
        return PROCESS.getProcessCpuTime() - start;
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
