package masl.bench;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import masl.bench.jade.AclPingPong;
import masl.bench.jade.BridgePingPong;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;

/**
 * {@code gradle bench}: runs MASL and its baselines side by side in one JVM and prints tables of
 * throughput with ratios against the baselines. Every figure is the median of
 * {@value #RUNS} runs after one warm-up run, the runs of one row interleaved, so that a
 * disturbance of the machine hits every column alike. Not a test: nothing is asserted.
 *
 * <p>Arguments: {@code --sizes 10,100,1000,10000} (agent counts), {@code --seconds S} (rough time
 * per measurement, default 1), {@code --thread-limit N} (largest N run with one thread per agent,
 * default 1000), {@code --only lockstep,invocations,joining,translation,simulation,lsp,startup,scale,deployed}.
 */
public final class Bench {

    /** Measurements per figure, after a warm-up: the figure is their median. */
    static final int RUNS = 5;
    /**
     * The invocation and bridge rows take more runs. On 2 cores each of their JADE columns swings by a
     * quarter from one window to the next (at 10 pairs, 20 JADE threads), raw JADE as much as the
     * bridge, and a median of 5 left the bridge's ratio anywhere from 0.77x to 1.58x from one full run
     * to the next (docs/performance.md, "Method").
     */
    static final int INVOCATION_RUNS = 11;
    /**
     * Warm-up runs of each lock-step column (each a quarter of --seconds): MASL reached its steady
     * rate only after 2-3 s of stepping (measured, runs of 8,000 steps of 1,000 agents in one JVM:
     * 12,000-16,000 steps/s in the first runs, 28,000-34,000 from the fourth or fifth); one short
     * warm-up run measured that settling, not the steps.
     */
    private static final int LOCK_STEP_WARM_UPS = 8;
    private static final int TRANSLATION_WARM_UP = 10;
    /** Set in a JVM the bench started for one section, which prints no header of its own. */
    private static final String OWN_JVM = "masl.bench.ownJvm";

    public static void main(String[] args) throws Exception {
        Options options = Options.parse(args);
        if (System.getProperty(OWN_JVM) == null) {
            System.out.printf(Locale.ROOT, "MASL benchmarks on %d cores, %s %s, max heap %d MiB, %s%n%n",
                    Runtime.getRuntime().availableProcessors(), System.getProperty("java.vm.name"),
                    System.getProperty("java.version"), Runtime.getRuntime().maxMemory() >> 20, loadAverage());
        }
        if (options.runs("lockstep")) {
            if (options.only().equals(List.of("lockstep"))) {
                lockStep(options);
            } else {
                lockStepInOwnJvm(options);
            }
        }
        if (options.runs("invocations")) {
            invocations(options);
        }
        if (options.runs("joining")) {
            joining();
        }
        if (options.runs("translation")) {
            translation();
        }
        if (options.runs("simulation")) {
            simulation();
        }
        if (options.runs("lsp")) {
            lsp();
        }
        if (options.runs("startup")) {
            startUp();
        }
        if (options.runs("scale")) {
            scale();
        }
        if (options.runs("deployed")) {
            deployed(options);
        }
        // A JADE platform that failed to shut down (closeQuietly) leaves threads that are not daemons:
        // they must not keep the benchmark, and `gradle bench` with it, from ending. Its AMS's shutdown
        // hook would wait for good on the agent table the failure left locked: then the JVM halts.
        if (jadeLeftRunning) {
            System.out.flush();
            Runtime.getRuntime().halt(0);
        }
        System.exit(0);
    }

    /** Whether a JADE platform of the bench failed to shut down ({@link #closeQuietly}). */
    private static volatile boolean jadeLeftRunning;

    /**
     * Synchronous round trips between agent pairs: MASL in-process against JADE's ACL ping-pong in
     * one container (item 2), and JADE pingers invoking MASL agents through the bridge against the
     * same raw JADE figure (item 3, as a ratio of round-trip times).
     */
    private static void invocations(Options options) throws Exception {
        System.out.println("2. Invocations: synchronous round trips per second between agent pairs (median of "
                + INVOCATION_RUNS + ")");
        System.out.println("3. Bridge: JADE pingers invoking MASL agents through --platform jade, against raw JADE");
        System.out.printf(Locale.ROOT, "%6s | %14s | %14s | %10s | %14s | %18s | %14s%n", "pairs", "JADE ACL",
                "MASL in-proc", "MASL/JADE", "JADE->bridge", "bridge/JADE time", "each round");
        Duration window = Duration.ofMillis((long) (options.seconds * 1000));
        Duration warmUp = window.dividedBy(2);
        JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer());
        try {
            for (int pairs : new int[] {1, 10}) {
                Map<String, double[]> runs = interleaved(INVOCATION_RUNS, List.of(
                        new Measure("jade", () -> AclPingPong.measure(platform, pairs, warmUp, window).roundTripsPerSecond()),
                        new Measure("masl", MaslPingPong.prepare(pairs, (int) (options.seconds * 400_000 / pairs))),
                        new Measure("bridge", () -> BridgePingPong.measure(platform, pairs, warmUp, window).roundTripsPerSecond())));
                double jade = median(runs.get("jade"));
                double masl = median(runs.get("masl"));
                double bridge = median(runs.get("bridge"));
                System.out.printf(Locale.ROOT, "%6d | %14s | %14s | %10s | %14s | %18s | %14s%n", pairs, rate(jade),
                        rate(masl), ratio(masl, jade), rate(bridge), ratio(jade, bridge),
                        roundRatios(runs.get("jade"), runs.get("bridge")));
            }
        } finally {
            closeQuietly(platform);
        }
        System.out.println("   (goals: MASL/JADE >= 3x; bridge/JADE round-trip time <= 1.2x;"
                + " each round: the lowest and highest bridge/JADE of one round's two windows, side by side)");
        System.out.println();
    }

    /** The range of {@code jade[i] / bridge[i]}, the ratio of each round's two measurements. */
    private static String roundRatios(double[] jade, double[] bridge) {
        double lowest = Double.MAX_VALUE;
        double highest = 0;
        for (int i = 0; i < jade.length; i++) {
            lowest = Math.min(lowest, jade[i] / bridge[i]);
            highest = Math.max(highest, jade[i] / bridge[i]);
        }
        return String.format(Locale.ROOT, "%.2f-%.2fx", lowest, highest);
    }

    /** Item 4: N agents entering a synchronous block and passing its entry barrier. */
    private static void joining() throws Exception {
        System.out.println("4. Joining: time for N agents to enter a synchronous block and pass its entry barrier (median of " + RUNS + ")");
        System.out.printf(Locale.ROOT, "%8s | %14s | %14s%n", "N", "MASL", "goal");
        int agents = 1_000;
        Map<String, double[]> figures = interleaved(RUNS, List.of(new Measure("masl", () -> MaslJoining.prepare(agents).call())));
        System.out.printf(Locale.ROOT, "%8d | %12.3f s | %12s%n%n", agents, median(figures.get("masl")), "<= 0.1 s");
    }

    /**
     * Item 5: MASL source to Java source, javac left out. The first translation of a fresh JVM pays
     * for loading and compiling the translator: this table shows the first, then the median of
     * {@value #RUNS} after {@value #TRANSLATION_WARM_UP} more, as a build daemon or plug-in sees it.
     */
    private static void translation() throws Exception {
        System.out.println("5. Translation: MASL lines per second, source to Java source (javac excluded), generated 10,000-line program");
        System.out.println("   per second of elapsed time and of the translating thread's CPU time (what other jobs on the machine do not change)");
        System.out.printf(Locale.ROOT, "%26s | %14s | %14s | %12s%n", "", "elapsed", "thread CPU", "goal");
        int lines = 10_000;
        Callable<Double> elapsed = MaslTranslation.prepare(lines, false);
        Callable<Double> cpu = MaslTranslation.prepare(lines, true);
        System.out.printf(Locale.ROOT, "%26s | %14s | %14s | %12s%n", "first in this JVM (cpu)", "-", rate(cpu.call()), "");
        // What masl run pays without its cache, in fresh JVMs started as the command starts them.
        Map<String, double[]> cold = interleaved(RUNS, List.of(
                new Measure("archive", () -> ColdTranslation.measure(lines, true)),
                new Measure("plain", () -> ColdTranslation.measure(lines, false))));
        System.out.printf(Locale.ROOT, "%26s | %14s | %14s | %12s%n", "fresh JVM, masl.jsa", "-",
                rate(median(cold.get("archive"))), ">= 50,000");
        System.out.printf(Locale.ROOT, "%26s | %14s | %14s | %12s%n", "fresh JVM, no archive", "-",
                rate(median(cold.get("plain"))), "");
        for (int i = 0; i < TRANSLATION_WARM_UP; i++) {
            elapsed.call();
        }
        Map<String, double[]> figures = interleaved(RUNS, List.of(new Measure("elapsed", elapsed), new Measure("cpu", cpu)));
        System.out.printf(Locale.ROOT, "%26s | %14s | %14s | %12s%n%n", "warm, median of " + RUNS,
                rate(median(figures.get("elapsed"))), rate(median(figures.get("cpu"))), ">= 50,000");
        translationScaling();
    }

    /** Item 5, continued: the time of twice the input, {@link TranslationScaling}. */
    private static void translationScaling() throws Exception {
        System.out.println("   twice the input: process CPU seconds, median of " + RUNS + " (" + loadAverage() + ")");
        System.out.printf(Locale.ROOT, "%26s | %12s | %12s | %12s | %12s | %12s%n", "", "check", "check 2x", "translate",
                "translate 2x", "ratios");
        for (TranslationScaling.Row row : TranslationScaling.ROWS) {
            String small = row.program().apply(row.size());
            String large = row.program().apply(2 * row.size());
            Map<String, double[]> figures = interleaved(RUNS, List.of(new Measure("check", TranslationScaling.check(small)),
                    new Measure("check 2x", TranslationScaling.check(large)), new Measure("translate", TranslationScaling.translate(small)),
                    new Measure("translate 2x", TranslationScaling.translate(large))));
            double[] medians = figures.values().stream().mapToDouble(Bench::median).toArray();
            System.out.printf(Locale.ROOT, "%26s | %12.3f | %12.3f | %12.3f | %12.3f | %5.2f, %5.2f%n", row.size() + " " + row.name(),
                    medians[0], medians[1], medians[2], medians[3], medians[1] / medians[0], medians[3] / medians[2]);
        }
        System.out.println("   (linear: ratios near 2)");
        System.out.println();
    }

    /** Item 6: robots driven by MASL against a bare ode4j loop over the same bodies. */
    private static void simulation() throws Exception {
        System.out.println("6. Simulation: " + MaslSimulation.ROBOTS + " wheeled robots, step 0.01 s, lock-step, simulated seconds "
                + "per second of elapsed time and of process CPU time (median of " + RUNS + ")");
        System.out.printf(Locale.ROOT, "%8s | %14s | %14s | %12s | %14s | %14s | %12s%n", "robots", "MASL", "bare ode4j",
                "MASL/bare", "MASL (cpu)", "bare (cpu)", "MASL/bare");
        MaslSimulation simulation = MaslSimulation.prepare();
        // ode4j's code is still being compiled after one run of each: the first runs would measure the JIT.
        Map<String, double[]> figures = interleaved(2, RUNS, List.of(new Measure("masl", simulation.masl(false)),
                new Measure("bare", simulation.bare(false)), new Measure("masl-cpu", simulation.masl(true)),
                new Measure("bare-cpu", simulation.bare(true))));
        double masl = median(figures.get("masl"));
        double bare = median(figures.get("bare"));
        double maslCpu = median(figures.get("masl-cpu"));
        double bareCpu = median(figures.get("bare-cpu"));
        System.out.printf(Locale.ROOT, "%8d | %14.2f | %14.2f | %12s | %14.2f | %14.2f | %12s%n", MaslSimulation.ROBOTS,
                masl, bare, ratio(masl, bare), maslCpu, bareCpu, ratio(maslCpu, bareCpu));
        System.out.println("   (goal: MASL/bare >= 0.8x)");
        System.out.println();
    }

    /** The editor's wait for diagnostics after a change, {@link LspLatency}. */
    private static void lsp() throws Exception {
        System.out.println("7. Editor: masl lsp's diagnostics after a one-line change to a generated " + String.format(Locale.ROOT,
                "%,d", LspLatency.LINES) + "-line program, from didChange sent to publishDiagnostics received");
        LspLatency.Figures figures = LspLatency.measure();
        double[] sorted = figures.changes().clone();
        java.util.Arrays.sort(sorted);
        System.out.println("   elapsed per change, and process CPU time per change (what other jobs on the machine do not change)");
        System.out.printf(Locale.ROOT, "%8s | %10s | %10s | %10s | %14s | %15s | %10s%n", "changes", "median", "p90", "max",
                "CPU per change", "first, on open", "goal");
        System.out.printf(Locale.ROOT, "%8d | %7.1f ms | %7.1f ms | %7.1f ms | %11.1f ms | %12.1f ms | %10s%n%n",
                sorted.length, median(sorted), sorted[(int) Math.ceil(sorted.length * 0.9) - 1], sorted[sorted.length - 1],
                figures.cpuPerChange(), figures.open(), "<= 200 ms");
    }

    /**
     * {@code masl run} as whole processes, {@link StartUp}: before the cache, a first run and a second
     * run of the unchanged program, and {@code masl check}, interleaved; on the bench's JDK (17) with
     * the class-data archive, and on the JDK 25 installing found with its ahead-of-time cache.
     */
    private static void startUp() throws Exception {
        System.out.println("8. Start-up: masl run and masl check of a new mission (missions/hello.masl under another name) as whole"
                + " processes of the installed command, elapsed and the process's CPU time (median of " + RUNS + ", "
                + loadAverage() + ")");
        StartUp jdk17 = StartUp.installed(Path.of(System.getProperty("java.home")));
        Optional<Path> aheadOfTimeJdk = StartUp.aheadOfTimeJdk();
        Optional<StartUp> jdk25 = aheadOfTimeJdk.isPresent() ? Optional.of(StartUp.installed(aheadOfTimeJdk.get())) : Optional.empty();
        try {
            Map<String, List<StartUp.Timing>> timings = new LinkedHashMap<>();
            List<Measure> measures = new ArrayList<>(List.of(
                    new Measure("before", () -> record(timings, "before", jdk17.before())),
                    new Measure("first", () -> record(timings, "first", jdk17.first())),
                    new Measure("second", () -> record(timings, "second", jdk17.second())),
                    new Measure("check C2", () -> record(timings, "check C2", jdk17.check(true))),
                    new Measure("check", () -> record(timings, "check", jdk17.check(false))),
                    new Measure("check again", () -> record(timings, "check again", jdk17.checkAgain())),
                    new Measure("run after check", () -> record(timings, "run after check", jdk17.runAfterCheck()))));
            jdk25.ifPresent(startUp -> measures.addAll(List.of(
                    new Measure("first 25", () -> record(timings, "first 25", startUp.first())),
                    new Measure("second 25", () -> record(timings, "second 25", startUp.second())),
                    new Measure("check 25", () -> record(timings, "check 25", startUp.check(false))))));
            Map<String, double[]> figures = interleaved(RUNS, measures);
            System.out.printf(Locale.ROOT, "%-58s | %10s | %10s | %10s%n", "", "elapsed", "CPU", "goal");
            printStartUp("JDK 17 before: --no-cache, the JDK's class-data archive", figures, timings, "before", "");
            printStartUp("JDK 17 first run: empty cache, lib/masl.jsa", figures, timings, "first", "<= 0.6 s");
            printStartUp("JDK 17 second run: the mission from the cache", figures, timings, "second", "<= 0.4 s");
            printStartUp("JDK 17 masl check, C1 and C2 (-XX:TieredStopAtLevel=4)", figures, timings, "check C2", "");
            printStartUp("JDK 17 masl check, C1 alone (the command's JIT)", figures, timings, "check", "<= 0.4 s");
            printStartUp("JDK 17 masl check again: the unchanged program, cached", figures, timings, "check again", "");
            printStartUp("JDK 17 run after a check: the program it left cached", figures, timings, "run after check", "");
            if (jdk25.isPresent()) {
                printStartUp("JDK 25 first run: empty cache, lib/masl.aot", figures, timings, "first 25", "<= 0.6 s");
                printStartUp("JDK 25 second run: the mission from the cache", figures, timings, "second 25", "<= 0.4 s");
                printStartUp("JDK 25 masl check, C1 alone", figures, timings, "check 25", "<= 0.4 s");
            } else {
                System.out.println("   (no JDK 25: installing found none, so it made no lib/masl.aot)");
            }
        } finally {
            jdk17.close();
            if (jdk25.isPresent()) {
                jdk25.get().close();
            }
        }
        System.out.println();
    }

    /** {@link AgentScale}, 100,000 agents in a fresh JVM with the default heap. */
    private static void scale() throws Exception {
        int agents = 100_000;
        int steps = 1_000;
        System.out.println("9. Scale: " + String.format(Locale.ROOT, "%,d", agents) + " agents in one synchronous block, "
                + String.format(Locale.ROOT, "%,d", steps) + " steps, a fresh JVM with the default heap (median of 3, "
                + loadAverage() + ")");
        List<AgentScale.Figures> runs = new ArrayList<>();
        for (int run = 0; run < 3; run++) {
            runs.add(AgentScale.measure(agents, steps));
        }
        String first = "steps / s, 1-" + AgentScale.FIRST_STEPS;
        String after = "after step " + AgentScale.FIRST_STEPS;
        System.out.printf(Locale.ROOT, "%10s | %14s | %14s | %18s | %18s | %16s%n", "N", "start", "start (CPU)", first, after,
                "bytes per agent");
        System.out.printf(Locale.ROOT, "%10s | %12.2f s | %12.2f s | %18s | %18s | %16s%n", String.format(Locale.ROOT, "%,d", agents),
                median(runs.stream().mapToDouble(AgentScale.Figures::startSeconds).toArray()),
                median(runs.stream().mapToDouble(AgentScale.Figures::startCpuSeconds).toArray()),
                rate(median(runs.stream().mapToDouble(AgentScale.Figures::stepsPerSecond).toArray())),
                rate(median(runs.stream().mapToDouble(AgentScale.Figures::laterStepsPerSecond).toArray())),
                rate(median(runs.stream().mapToDouble(AgentScale.Figures::bytesPerAgent).toArray())));
        System.out.println("   (start: the program's text to the end of its first step, translating and javac included;"
                + " the fresh JVM still compiles the runtime during the first steps;");
        System.out.println("    goals: start <= 5 s, >= 100 steps/s, a long mission's rate: after step " + AgentScale.FIRST_STEPS + ")");
        System.out.println();
    }

    /**
     * Item 10: agents' programs deployed over two containers in two other JVMs, {@link DeployedMissions};
     * lock-step, then a sensor loop of ten own primitives deployed against placed against in-process.
     */
    private static void deployed(Options options) throws Exception {
        int runs = 3;
        System.out.println("10. Deployed: agents spread over two masl container JVMs of the installed command (--deploy '*=c2+c3',"
                + " --place likewise), the mission in this JVM; steps per second and messages per step and container,"
                + " sent/taken by the coordinator (median of " + runs + ", " + loadAverage() + ")");
        DeployedMissions missions = DeployedMissions.installed();
        JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer());
        try {
            System.out.printf(Locale.ROOT, "%-44s | %8s | %12s | %12s | %12s | %12s | %22s | %12s%n", "", "N", "steps / s",
                    "later half", "msgs to c", "msgs from c", "CPU ms/step: mission", "containers");
            // Long enough for the later half to run after the JIT has compiled the new program's code;
            // N = 1,000: longer, since its JIT goes on compiling for longer.
            int stepsOf100 = (int) Math.max(10, options.seconds() * 2_000);
            int stepsOf1000 = (int) Math.max(10, options.seconds() * 3_000);
            Callable<DeployedMissions.Figures> of100 = missions.prepare(platform,
                    DeployedMissions.lockStep(100, stepsOf100), DeployedMissions.Where.DEPLOYED);
            Callable<DeployedMissions.Figures> of1000 = missions.prepare(platform,
                    DeployedMissions.lockStep(1_000, stepsOf1000), DeployedMissions.Where.DEPLOYED);
            // The serving containers' first mission is their JIT's: not one of a row's.
            of1000.call();
            List<List<DeployedMissions.Figures>> lockStep = interleavedFigures(runs, List.of(of100, of1000));
            Rates rateOf100 = printDeployed("lock-step, deployed", 100, lockStep.get(0));
            Rates rateOf1000 = printDeployed("lock-step, deployed", 1_000, lockStep.get(1));
            printStepCost(rateOf100.later(), rateOf1000.later());
            int agents = 10;
            int steps = (int) Math.max(10, options.seconds() * 200);
            String source = DeployedMissions.tenOwnPrimitives(agents, steps);
            List<List<DeployedMissions.Figures>> figures = interleavedFigures(runs, List.of(
                    missions.prepare(platform, source, DeployedMissions.Where.DEPLOYED),
                    missions.prepare(platform, source, DeployedMissions.Where.PLACED),
                    missions.prepare(platform, source, DeployedMissions.Where.IN_PROCESS)));
            Rates deployed = printDeployed("ten own primitives a step, deployed", agents, figures.get(0));
            Rates placed = printDeployed("ten own primitives a step, placed", agents, figures.get(1));
            Rates inProcess = printDeployed("ten own primitives a step, in-process", agents, figures.get(2));
            System.out.printf(Locale.ROOT, "   deployed/placed %s (later half %s), in-process/deployed %s (later half %s)%n",
                    ratio(deployed.whole(), placed.whole()), ratio(deployed.later(), placed.later()),
                    ratio(inProcess.whole(), deployed.whole()), ratio(inProcess.later(), deployed.later()));
        } finally {
            closeQuietly(platform);
            missions.close();
        }
        System.out.println("   (later half: the rate over the later half of the steps; the containers serve one mission after"
                + " another (--serve), from a warm-up one on;");
        System.out.println("    CPU ms/step: every thread of this JVM, and of the two containers' together, over the later"
                + " half; their sum over " + Runtime.getRuntime().availableProcessors() + " cores is the shortest step"
                + " the machine allows them;");
        System.out.println("    goals: >= 1,000 steps/s at N=1000 deployed; deployed/placed >= 10x)");
        System.out.println();
    }

    /** Runs each measure once as a warm-up, then {@code runs} rounds of them in turn; the figures of each. */
    private static List<List<DeployedMissions.Figures>> interleavedFigures(int runs, List<Callable<DeployedMissions.Figures>> measures)
            throws Exception {
        List<List<DeployedMissions.Figures>> figures = new ArrayList<>();
        for (Callable<DeployedMissions.Figures> measure : measures) {
            measure.call();
            figures.add(new ArrayList<>());
        }
        for (int round = 0; round < runs; round++) {
            for (int i = 0; i < measures.size(); i++) {
                figures.get(i).add(measures.get(i).call());
            }
        }
        return figures;
    }

    /**
     * What a deployed lock-step step costs whatever its size, and per agent, from the later halves of
     * N = 100 and 1,000: a step's time is taken as the one plus N times the other. The goal of 1,000
     * steps per second at N = 1,000 leaves 1 ms less the fixed part for 1,000 agents.
     */
    private static void printStepCost(double ratePer100, double ratePer1000) {
        double stepOf100 = 1_000.0 / ratePer100;
        double stepOf1000 = 1_000.0 / ratePer1000;
        double perAgentMicros = (stepOf1000 - stepOf100) * 1_000.0 / 900;
        double fixedMillis = stepOf100 - 100 * perAgentMicros / 1_000.0;
        System.out.printf(Locale.ROOT, "   a step, later halves: %.2f ms whatever its size + %.2f us per agent; the goal at"
                + " N=1000 leaves %.2f us per agent%n", fixedMillis, perAgentMicros, Math.max(0, 1.0 - fixedMillis));
    }

    /** Median steps per second of a deployed row, over the whole mission and over its later half. */
    private record Rates(double whole, double later) { }

    /** Prints a row of medians; its steps per second over the whole mission and over its later half. */
    private static Rates printDeployed(String row, int agents, List<DeployedMissions.Figures> runs) {
        double rate = median(runs.stream().mapToDouble(DeployedMissions.Figures::stepsPerSecond).toArray());
        double later = median(runs.stream().mapToDouble(DeployedMissions.Figures::laterStepsPerSecond).toArray());
        System.out.printf(Locale.ROOT, "%-44s | %8d | %12s | %12s | %12.1f | %12.1f | %22s | %12s%n", row, agents,
                rate(rate), rate(later),
                median(runs.stream().mapToDouble(DeployedMissions.Figures::toContainerPerStep).toArray()),
                median(runs.stream().mapToDouble(DeployedMissions.Figures::fromContainerPerStep).toArray()),
                millis(median(runs.stream().mapToDouble(figures -> figures.cpu().mission()).toArray())),
                millis(median(runs.stream().mapToDouble(figures -> figures.cpu().containers()).toArray())));
        return new Rates(rate, later);
    }

    /** A CPU time in milliseconds, or a dash where none was read. */
    private static String millis(double figure) {
        return Double.isNaN(figure) ? "-" : String.format(Locale.ROOT, "%.2f", figure);
    }

    private static double record(Map<String, List<StartUp.Timing>> timings, String row, StartUp.Timing timing) {
        timings.computeIfAbsent(row, name -> new ArrayList<>()).add(timing);
        return timing.elapsed();
    }

    /** Median and range; the CPU column skips the warm-up run, as the elapsed figures do. */
    private static void printStartUp(String row, Map<String, double[]> figures, Map<String, List<StartUp.Timing>> timings,
            String measure, String goal) {
        double[] elapsed = figures.get(measure);
        List<StartUp.Timing> all = timings.get(measure);
        double[] cpu = all.subList(1, all.size()).stream().mapToDouble(StartUp.Timing::cpu).sorted().toArray();
        double[] sorted = elapsed.clone();
        java.util.Arrays.sort(sorted);
        System.out.printf(Locale.ROOT, "%-58s | %8.2f s | %8.2f s | %10s   (elapsed %.2f-%.2f s, CPU %.2f-%.2f s)%n", row,
                median(elapsed), median(cpu), goal, sorted[0], sorted[sorted.length - 1], cpu[0], cpu[cpu.length - 1]);
    }

    /** A round trip of {@link CoreDistance}, or "-" if it could not be measured. */
    private static String distance(long nanos) {
        return nanos < 0 ? "-" : String.valueOf(nanos);
    }

    /** The machine's load average over the last minute, as /proc/loadavg gives it: the bench runs on shared machines. */
    static String loadAverage() {
        try {
            return "load average " + java.nio.file.Files.readString(java.nio.file.Path.of("/proc/loadavg")).split(" ")[0];
        } catch (java.io.IOException | RuntimeException unknown) {
            return "load average unknown";
        }
    }

    /** JADE 4.3 sometimes fails to shut its platform down: the figures are printed by then, and the other benchmarks still run. */
    private static void closeQuietly(JadePlatform platform) {
        try {
            platform.close();
        } catch (JadeException e) {
            jadeLeftRunning = true;
            System.out.println("   (JADE did not shut down cleanly: " + e.getMessage() + ")");
        }
    }

    /** One kind of measurement of a row. */
    private record Measure(String name, Callable<Double> run) { }

    /**
     * Runs every measure once as a warm-up, then {@code runs} rounds of all of them in turn, so that a
     * disturbance of the machine hits every column alike; the figures of each measure by name.
     */
    private static Map<String, double[]> interleaved(int runs, List<Measure> measures) throws Exception {
        return interleaved(1, runs, measures);
    }

    /** As {@link #interleaved(int, List)} after {@code warmUps} rounds of warm-up. */
    private static Map<String, double[]> interleaved(int warmUps, int runs, List<Measure> measures) throws Exception {
        for (int round = 0; round < warmUps; round++) {
            for (Measure measure : measures) {
                measure.run().call();
            }
        }
        Map<String, double[]> figures = new LinkedHashMap<>();
        for (Measure measure : measures) {
            figures.put(measure.name(), new double[runs]);
        }
        for (int round = 0; round < runs; round++) {
            for (Measure measure : measures) {
                figures.get(measure.name())[round] = measure.run().call();
            }
        }
        return figures;
    }

    static double median(double[] figures) {
        double[] sorted = figures.clone();
        java.util.Arrays.sort(sorted);
        int middle = sorted.length / 2;
        return sorted.length % 2 == 1 ? sorted[middle] : (sorted[middle - 1] + sorted[middle]) / 2;
    }

    /**
     * The lock-step section in a JVM of its own: after its minutes of MASON, hand-written pools and
     * MASL stepping, the warm translation measured in the same JVM fell from about 95,000 to
     * 55,000-75,000 lines per second (why was not found).
     */
    private static void lockStepInOwnJvm(Options options) throws Exception {
        List<String> command = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-D" + OWN_JVM + "=true", "-cp", System.getProperty("java.class.path"), Bench.class.getName(), "--only", "lockstep",
                "--sizes", options.sizes().stream().map(String::valueOf).collect(Collectors.joining(",")),
                "--seconds", String.valueOf(options.seconds()), "--thread-limit", String.valueOf(options.threadLimit()));
        Process process = new ProcessBuilder(command).inheritIO().start();
        if (process.waitFor() != 0) {
            throw new IllegalStateException("the lock-step section's JVM ended with status " + process.exitValue());
        }
    }

    private static void lockStep(Options options) throws Exception {
        LockStepRun masl = MaslLockStep.onPool();
        LockStepRun pool = new TaskPoolWaves();
        LockStepRun threads = new PhaserThreads();
        LockStepRun maslThreads = MaslLockStep.threadPerAgent();
        LockStepRun mason = MasonLockStep.schedule();
        LockStepRun masonSequence = MasonLockStep.sequence();
        System.out.println("1. Lock-step: N agents in one synchronous block, steps per second (one barrier trip = one step),");
        System.out.println("   timed from the end of the first step to the end of the last (start-up left out), median of " + RUNS + ",");
        System.out.println("   each run about a quarter of --seconds long at the rate a first short run of its column showed, after "
                + LOCK_STEP_WARM_UPS + " warm-up runs;");
        System.out.println("   then steps per second of process CPU time over those runs (every thread of the JVM, start-up included),");
        System.out.println("   which other jobs on the machine change much less than elapsed time");
        System.out.printf(Locale.ROOT, "%8s | %12s | %12s | %12s | %12s | %10s | %12s || %12s | %12s | %10s || %12s | %12s | %11s | %9s || %11s%n",
                "N", "MASL (pool)", "2-thr pool", "thr+Phaser", "MASL thr", "MASL/pool", "MASL/threads",
                "MASL cpu", "pool cpu", "MASL/pool", "MASON Sched", "MASON Seq", "MASL/MASON", "MASL/Seq", "core RTT ns");
        for (int agents : options.sizes) {
            long distanceBefore = CoreDistance.roundTripNanos();
            List<LockStepRun> runs = new ArrayList<>(List.of(masl, pool, mason, masonSequence));
            if (agents <= options.threadLimit) {
                runs.add(threads);
                runs.add(maslThreads);
            }
            Map<String, List<Long>> cpuTimes = new LinkedHashMap<>();
            Map<String, Integer> stepsOf = new LinkedHashMap<>();
            List<Measure> measures = new ArrayList<>();
            for (LockStepRun run : runs) {
                int steps = calibratedSteps(run, agents, options.seconds);
                stepsOf.put(run.name(), steps);
                measures.add(new Measure(run.name(), () -> {
                    // Translating and compiling MASL's program is left out: prepare() does it.
                    Callable<Double> prepared = run.prepare(agents, steps);
                    long cpu = processCpuNanos();
                    double rate = prepared.call();
                    cpuTimes.computeIfAbsent(run.name(), name -> new ArrayList<>()).add(processCpuNanos() - cpu);
                    return rate;
                }));
            }
            Map<String, double[]> figures = interleaved(LOCK_STEP_WARM_UPS, RUNS, measures);
            Double maslRate = median(figures.get(masl.name()));
            Double poolRate = median(figures.get(pool.name()));
            Double threadRate = figures.containsKey(threads.name()) ? median(figures.get(threads.name())) : null;
            Double maslThreadRate = figures.containsKey(maslThreads.name()) ? median(figures.get(maslThreads.name())) : null;
            Double masonRate = median(figures.get(mason.name()));
            Double sequenceRate = median(figures.get(masonSequence.name()));
            double maslCpu = stepsPerCpuSecond(stepsOf.get(masl.name()), cpuTimes.get(masl.name()));
            double poolCpu = stepsPerCpuSecond(stepsOf.get(pool.name()), cpuTimes.get(pool.name()));
            long distanceAfter = CoreDistance.roundTripNanos();
            System.out.printf(Locale.ROOT, "%8d | %12s | %12s | %12s | %12s | %10s | %12s || %12s | %12s | %10s || %12s | %12s | %11s | %9s || %11s%n",
                    agents, rate(maslRate), rate(poolRate), rate(threadRate), rate(maslThreadRate), ratio(maslRate, poolRate),
                    ratio(maslRate, threadRate), rate(maslCpu), rate(poolCpu), ratio(maslCpu, poolCpu),
                    rate(masonRate), rate(sequenceRate), ratio(maslRate, masonRate), ratio(maslRate, sequenceRate),
                    distance(distanceBefore) + "/" + distance(distanceAfter));
        }
        System.out.printf(Locale.ROOT, "   (thr+Phaser: hand-written, a platform thread per agent on a Phaser; MASL thr: MASL's thread-per-agent"
                + " driver, masl run --threads; neither run above N=%d;%n    MASON Sched: MASON 14, each agent scheduleRepeating;"
                + " MASON Seq: one Sequence on one thread, the floor, and MASL/Seq MASL's distance to it;%n"
                + "    goal: MASL/MASON >= 2x at N=1000 and 10000;%n"
                + "    core RTT: a round trip between two threads through one word before/after the row (CoreDistance): above"
                + " about 150 ns the two CPUs are far apart, and two-worker lock-step runs slower)%n%n",
                options.threadLimit);
    }

    /**
     * Steps per CPU second over all the runs after the warm-up together: the process's CPU time is
     * counted in ticks of 10 ms here, too coarse for one short run on a loaded machine.
     */
    private static double stepsPerCpuSecond(int stepsPerRun, List<Long> cpuNanosPerRun) {
        List<Long> measured = cpuNanosPerRun.subList(cpuNanosPerRun.size() - RUNS, cpuNanosPerRun.size());
        return (double) stepsPerRun * measured.size() / (measured.stream().mapToLong(Long::longValue).sum() / 1e9);
    }

    static long processCpuNanos() {
        return ((com.sun.management.OperatingSystemMXBean) java.lang.management.ManagementFactory.getOperatingSystemMXBean())
                .getProcessCpuTime();
    }

    /**
     * Steps for one run of about a quarter of {@code seconds} at the rate a first run of
     * {@link #stepsFor} steps showed, never fewer: a run of a few milliseconds measures the start
     * of a mission and the compiler's warming, not its steps (the pool and MASON step 1,000 agents
     * 20,000-30,000 times a second, while a thread per agent steps them about 100 times).
     */
    private static int calibratedSteps(LockStepRun run, int agents, double seconds) throws Exception {
        int first = stepsFor(agents, seconds);
        double rate = run.prepare(agents, first).call();
        return (int) Math.max(first, Math.min(rate * seconds / 4, 1_000_000));
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
