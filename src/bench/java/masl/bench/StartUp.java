package masl.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.Stream;

/**
 * {@code masl run} of a copy of {@code missions/hello.masl} under another name, a mission the install's
 * training run never saw, as whole processes of the installed command ({@code masl-cli/build/install},
 * which {@code gradle bench} installs first) on one JDK, elapsed time and the child's CPU time (user and
 * system, from this JVM's {@code /proc/self/stat} once the child is reaped):
 *
 * <ul>
 *   <li>before: {@code --no-cache} on the JDK's own class-data archive, as masl ran before the cache;</li>
 *   <li>first: an empty cache, on what installing made for the JDK ({@code lib/masl.jsa}, or on a JDK 25
 *       {@code lib/masl.aot});</li>
 *   <li>second: the same again, the mission found in the cache.</li>
 * </ul>
 *
 * <p>And {@code masl check} of the same program, which the start script runs on C1 alone, against the
 * same with C2 given back ({@code -XX:TieredStopAtLevel=4} in {@code JAVA_OPTS}); then what a check
 * leaves in the cache gives: a second check of the unchanged program, and a run after a check.
 */
final class StartUp {

    /** The kernel's clock ticks per second for {@code /proc} times (USER_HZ, 100 on Linux). */
    private static final double TICKS_PER_SECOND = 100;

    private final Path masl;
    private final Path javaHome;
    private final Path caches;
    private final Path program;

    /** Elapsed seconds and CPU seconds of one process. */
    record Timing(double elapsed, double cpu) { }

    StartUp(Path masl, Path javaHome, Path mission) throws IOException {
        this.masl = masl;
        this.javaHome = javaHome;
        this.caches = Files.createTempDirectory("masl-bench-cache");
        this.program = Files.copy(mission, caches.resolve("startup.masl"));
    }

    /** The installed command on {@code javaHome}. */
    static StartUp installed(Path javaHome) throws IOException {
        Path home = Path.of(System.getProperty("masl.bench.home", ".")).toAbsolutePath();
        Path masl = home.resolve("masl-cli/build/install/masl/bin/masl");
        if (!Files.isExecutable(masl)) {
            throw new IllegalStateException(masl + " is missing: gradle bench installs it (:masl-cli:installDist)");
        }
        return new StartUp(masl, javaHome, home.resolve("missions/hello.masl"));
    }

    /** The JDK 25 or later installing made {@code lib/masl.aot} with ({@code masl-cli/build.gradle}), if it found one. */
    static Optional<Path> aheadOfTimeJdk() {
        String jdk = System.getProperty("masl.bench.aotJdk", "");
        return jdk.isEmpty() ? Optional.empty() : Optional.of(Path.of(jdk));
    }

    /** Without the cache, on the JDK's default class-data archive: masl as it was. */
    Timing before() throws Exception {
        Path jdkArchive = javaHome.resolve("lib/server/classes.jsa");
        return run(Files.createTempDirectory(caches, "before"), "-XX:SharedArchiveFile=" + jdkArchive, "--no-cache");
    }

    /** A first run: nothing cached yet. */
    Timing first() throws Exception {
        return run(Files.createTempDirectory(caches, "first"), "");
    }

    /** A second run of the unchanged program: a cache one run has filled. */
    Timing second() throws Exception {
        Path cache = caches.resolve("warm");
        if (!Files.isDirectory(cache)) {
            run(cache, "");
        }
        return run(cache, "");
    }

    /**
     * {@code masl check} of the new program (an empty cache: a check stores what it compiled there):
     * on C1 alone, as the command runs it, or with C2 too.
     */
    Timing check(boolean withC2) throws Exception {
        return time("check", Files.createTempDirectory(caches, "check"), withC2 ? "-XX:TieredStopAtLevel=4" : "");
    }

    /** {@code masl check} of the unchanged program, which a first check left in the cache. */
    Timing checkAgain() throws Exception {
        return time("check", checked(), "");
    }

    /** {@code masl run} of the program a check left in the cache: a check, then a run. */
    Timing runAfterCheck() throws Exception {
        return run(checked(), "");
    }

    /** A cache one {@code masl check} of the program has filled. */
    private Path checked() throws Exception {
        Path cache = caches.resolve("checked");
        if (!Files.isDirectory(cache)) {
            time("check", cache, "");
        }
        return cache;
    }

    private Timing run(Path cache, String javaOptions, String... options) throws Exception {
        return time("run", cache, javaOptions, options);
    }

    private Timing time(String subcommand, Path cache, String javaOptions, String... options) throws Exception {
        List<String> command = new ArrayList<>(List.of(masl.toString(), subcommand, program.toString()));
        command.addAll(List.of(options));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true);
        Map<String, String> environment = builder.environment();
        environment.put("MASL_CACHE_DIR", cache.toString());
        environment.put("JAVA_HOME", javaHome.toString());
        environment.put("JAVA_OPTS", javaOptions);
        environment.remove("MASL_OPTS");
        environment.remove("MASL_JAVA_HOME");
        long cpuBefore = childrenCpuTicks();
        long start = System.nanoTime();
        Process process = builder.start();
        String output = new String(process.getInputStream().readAllBytes());
        int status = process.waitFor();
        double elapsed = (System.nanoTime() - start) / 1e9;
        // run: the journal's line, after the progress line masl writes if compiling takes a second (a loaded machine).
        if (status != 0 || subcommand.equals("run") && output.lines().noneMatch(line -> line.startsWith("Hello from agent"))) {
            throw new IllegalStateException("masl " + subcommand + " failed (" + status + "): " + output);
        }
        return new Timing(elapsed, (childrenCpuTicks() - cpuBefore) / TICKS_PER_SECOND);
    }

    /** cutime + cstime of this process: the CPU time of its children that have ended. */
    private static long childrenCpuTicks() throws IOException {
        String stat = Files.readString(Path.of("/proc/self/stat"));
        String[] fields = stat.substring(stat.lastIndexOf(')') + 2).split(" ");
        // After the command name: state is field 3 of stat(5), cutime 16 and cstime 17.
        return Long.parseLong(fields[13]) + Long.parseLong(fields[14]);
    }

    void close() throws IOException {
        try (Stream<Path> files = Files.walk(caches)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(file);
            }
        }
    }
}
