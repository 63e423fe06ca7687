package masl.bench;

import com.sun.management.OperatingSystemMXBean;
import java.lang.management.ManagementFactory;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.IntFunction;
import java.util.function.Predicate;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.descriptor.AgentPath;
import masl.translator.Frontend;
import masl.translator.Translator;
import masl.translator.source.SourceFile;

/**
 * How the time of checking and translating grows with the program: a team declared on one line, and
 * the translation benchmark's program of many blocks ({@link MaslTranslation#source}), each at a size
 * and at twice that size. Linear work takes twice as long for twice the input; checking a team once compared each name with every name before it, and
 * 100,000 agents took 100 s to check. The translator's tests count the bytes allocated instead
 * (TranslationScaleTest), a count that does not depend on the machine's load.
 */
final class TranslationScaling {

    /** One program and its size: the sizes take most of a second, so that one collection does not decide. */
    record Row(String name, IntFunction<String> program, int size) { }

    static final List<Row> ROWS = List.of(new Row("agents", TranslationScaling::team, 400_000),
            new Row("lines", MaslTranslation::source, 40_000));

    private static final OperatingSystemMXBean PROCESS =
            (OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();

    private TranslationScaling() {
    }

    /** Checking {@code source} (parse and analysis), in seconds of the process's CPU time. */
    static Callable<Double> check(String source) {
        SourceFile file = SourceFile.of("scale.masl", source);
        return () -> cpuSeconds(file, program -> new Frontend(AgentPath.parse("")).analyse(program).succeeded());
    }

    /** Translating {@code source} to Java source, in seconds of the process's CPU time. */
    static Callable<Double> translate(String source) {
        SourceFile file = SourceFile.of("scale.masl", source);
        return () -> cpuSeconds(file, program -> new Translator(AgentPath.parse("")).translate(program).succeeded());
    }

    /**
     * The process's CPU time while {@code step} runs, not the calling thread's: checking and translating
     * run on a thread of their own with a deep stack. CPU time, not elapsed time: other jobs on the
     * machine lengthen the second, not the first.
     */
    private static double cpuSeconds(SourceFile source, Predicate<SourceFile> step) {
        // The garbage of the previous measurement is not this one's to collect.
        System.gc();
        long start = PROCESS.getProcessCpuTime();
        if (!step.test(source)) {
            throw new IllegalStateException("the benchmark's program does not translate");
        }
        return (PROCESS.getProcessCpuTime() - start) / 1e9;
    }

    /** {@code agents} Default agents on one declaration line and a one-statement program. */
    static String team(int agents) {
        return "import Default.xml as Default;\nDefault " + IntStream.range(0, agents).mapToObj(i -> "a" + i)
                .collect(Collectors.joining(", ")) + " = newAgent(Default);\nscalar entry main (true) { .logln(\"done\"); }\n";
    }
}
