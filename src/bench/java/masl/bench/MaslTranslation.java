package masl.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import masl.runtime.descriptor.AgentPath;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;

/**
 * The translation benchmark: MASL lines per second from source text to Java
 * source text (parsing, analysis against the descriptors, generation; javac left out), on a
 * generated program of about {@code lines} lines: one {@code main} holding a sequence of
 * asynchronous blocks, each with locals, a loop, a condition, a shared update and primitive calls.
 */
final class MaslTranslation {

    private MaslTranslation() {
    }

    /**
     * The call translates the program once (a fresh translator) and returns lines per second of
     * elapsed time, or with {@code cpuTime} of the translating thread's processor time: on a machine
     * that other jobs load, the figure of the translator itself.
     */
    static Callable<Double> prepare(int lines, boolean cpuTime) {
        String source = source(lines);
        int lineCount = (int) source.lines().count();
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        return () -> onDeepStack(() -> {
            long start = cpuTime ? threads.getCurrentThreadCpuTime() : System.nanoTime();
            Translation translation = new Translator(AgentPath.parse("")).translateOnThisThread(SourceFile.of("big.masl", source));
            long elapsed = (cpuTime ? threads.getCurrentThreadCpuTime() : System.nanoTime()) - start;
            if (!translation.succeeded()) {
                throw new IllegalStateException("the benchmark's program does not translate: "
                        + translation.diagnostics().sorted());
            }
            return lineCount / (elapsed / 1e9);
        });
    }

    /**
     * {@code work} on a thread with the stack {@code Translator.translate} gives its own thread, so that
     * the translating thread's CPU time is this thread's.
     */
    private static double onDeepStack(Callable<Double> work) throws Exception {
        double[] result = new double[1];
        Exception[] failure = new Exception[1];
        Thread thread = new Thread(null, () -> {
            try {
                result[0] = work.call();
            } catch (Exception e) {
                failure[0] = e;
            }
        }, "bench translation", 256L << 20);
        thread.start();
        thread.join();
        if (failure[0] != null) {
            throw failure[0];
        }
        return result[0];
    }

    static String source(int lines) {
        List<String> out = new ArrayList<>(List.of(
                "import Default.xml as Default;",
                "Default a, b, c = newAgent(Default);",
                "asynchronous entry main (true) {",
                "  shared int total = 0;"));
        for (int k = 0; out.size() < lines - 1; k++) {
            out.addAll(List.of(
                    "  asynchronous entry block" + k + " (.getProxyID() != " + (k % 3) + ") {",
                    "    local int x" + k + " = 0;",
                    "    local int y" + k + " = 1;",
                    "    while (x" + k + " < 10) {",
                    "      x" + k + "++;",
                    "      y" + k + " = y" + k + " * 2 + x" + k + ";",
                    "    }",
                    "    if (y" + k + " > 100) { total += y" + k + "; } else { .logln(\"small \" + y" + k + "); }",
                    "    .nop();",
                    "  }",
                    "  total++;"));
        }
        out.add("}");
        return String.join("\n", out) + "\n";
    }
}
