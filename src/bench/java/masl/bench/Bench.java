package masl.bench;

import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import masl.jade.JadeOptions;
import masl.jade.JadePlatform;
import masl.jade.bench.AclPingPong;

/**
 * {@code gradle bench}: runs MASL and its baselines side by side in one JVM and prints tables of
 * throughput with ratios against the baselines (issue 13). Every measurement is the best of
 * {@value #ROUNDS} rounds after one warm-up round, the runs of one row interleaved, so that a
 * disturbance of the machine hits every column alike. Not a test: nothing is asserted.
 *
 * <p>Arguments: {@code --sizes 10,100,1000,10000} (agent counts), {@code --seconds S} (rough time
 * per measurement, default 1), {@code --thread-limit N} (largest N run with one thread per agent,
 * default 1000).
 */
public final class Bench {

    private static final int ROUNDS = 3;

    public static void main(String[] args) throws Exception {
        Options options = Options.parse(args);
        System.out.printf(Locale.ROOT, "MASL benchmarks on %d cores, %s %s, max heap %d MiB%n%n",
                Runtime.getRuntime().availableProcessors(), System.getProperty("java.vm.name"),
                System.getProperty("java.version"), Runtime.getRuntime().maxMemory() >> 20);
        if (options.runs("lockstep")) {
            lockStep(options);
        }
        if (options.runs("invocations")) {
            invocations(options);
        }
    }

    /**
     * The JADE baseline of the invocation benchmarks: ACL REQUEST/INFORM round trips in one
     * container. MASL's in-process and bridged invocations join this table when external
     * invocations are translated (issue 7).
     */
    private static void invocations(Options options) throws Exception {
        System.out.println("2. Invocations: synchronous round trips per second between agent pairs");
        System.out.printf(Locale.ROOT, "%8s | %20s | %20s%n", "pairs", "JADE ACL ping-pong", "MASL in-process");
        Duration window = Duration.ofMillis((long) (options.seconds * 1000));
        try (JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer())) {
            for (int pairs : new int[] {1, 10}) {
                double best = 0;
                for (int round = 0; round < ROUNDS; round++) {
                    best = Math.max(best, AclPingPong.measure(platform, pairs, window.dividedBy(2), window).roundTripsPerSecond());
                }
                System.out.printf(Locale.ROOT, "%8d | %20s | %20s%n", pairs, rate(best), "not translated yet");
            }
        }
        System.out.println();
    }

    private static void lockStep(Options options) throws Exception {
        LockStepRun masl = new MaslLockStep();
        LockStepRun pool = new TaskPoolWaves();
        LockStepRun threads = new PhaserThreads();
        System.out.println("1. Lock-step: N agents in one synchronous block, steps per second (one barrier trip = one step),");
        System.out.println("   timed from the end of the first step to the end of the last (start-up left out)");
        System.out.printf(Locale.ROOT, "%8s | %14s | %14s | %14s | %12s | %12s%n",
                "N", "MASL (pool)", pool.name().replace("Java tasks, ", ""), "threads+Phaser", "MASL/pool", "MASL/threads");
        for (int agents : options.sizes) {
            int steps = stepsFor(agents, options.seconds);
            Map<LockStepRun, Double> best = new LinkedHashMap<>();
            List<LockStepRun> runs = new ArrayList<>(List.of(masl, pool));
            if (agents <= options.threadLimit) {
                runs.add(threads);
            }
            for (LockStepRun run : runs) {
                run.prepare(agents, Math.max(2, steps / 10)).call();
            }
            for (int round = 0; round < ROUNDS; round++) {
                for (LockStepRun run : runs) {
                    Callable<Double> prepared = run.prepare(agents, steps);
                    best.merge(run, prepared.call(), Math::max);
                }
            }
            Double maslRate = best.get(masl);
            Double poolRate = best.get(pool);
            Double threadRate = best.get(threads);
            System.out.printf(Locale.ROOT, "%8d | %14s | %14s | %14s | %12s | %12s%n", agents,
                    rate(maslRate), rate(poolRate), rate(threadRate), ratio(maslRate, poolRate), ratio(maslRate, threadRate));
        }
        System.out.printf(Locale.ROOT, "   (threads+Phaser not run above N=%d: one platform thread per agent)%n%n", options.threadLimit);
    }

    /** Enough steps for about {@code seconds} at the rates seen on a 2-core machine. */
    private static int stepsFor(int agents, double seconds) {
        return (int) Math.max(10, seconds * 2_000_000 / agents / 10);
    }

    private static String rate(Double perSecond) {
        return perSecond == null ? "-" : String.format(Locale.ROOT, "%,.0f", perSecond);
    }

    private static String ratio(Double value, Double baseline) {
        return value == null || baseline == null ? "-" : String.format(Locale.ROOT, "%.2fx", value / baseline);
    }

    private record Options(List<Integer> sizes, double seconds, int threadLimit, List<String> only) {

        boolean runs(String benchmark) {
            return only.isEmpty() || only.contains(benchmark);
        }

        static Options parse(String[] args) {
            List<Integer> sizes = List.of(10, 100, 1_000, 10_000);
            double seconds = 1;
            int threadLimit = 1_000;
            List<String> only = List.of();
            for (int i = 0; i + 1 < args.length; i += 2) {
                switch (args[i]) {
                    case "--sizes" -> sizes = java.util.Arrays.stream(args[i + 1].split(",")).map(Integer::valueOf).toList();
                    case "--seconds" -> seconds = Double.parseDouble(args[i + 1]);
                    case "--thread-limit" -> threadLimit = Integer.parseInt(args[i + 1]);
                    case "--only" -> only = List.of(args[i + 1].split(","));
                    default -> throw new IllegalArgumentException("unknown option " + args[i]);
                }
            }
            return new Options(sizes, seconds, threadLimit, only);
        }
    }
}
