package masl.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

/**
 * {@code masl run missions/hello.masl} as whole processes of the installed command
 * ({@code masl-cli/build/install}, which {@code gradle bench} installs first), elapsed time and the
 * child's CPU time (user and system, from this JVM's {@code /proc/self/stat} once the child is reaped):
 *
 * <ul>
 *   <li>before: {@code --no-cache} on the JDK's own class-data archive, as masl ran before the cache;</li>
 *   <li>first: an empty cache, on the archive installing made ({@code lib/masl.jsa});</li>
 *   <li>second: the same again, the mission found in the cache.</li>
 * </ul>
 *
 * <p>And {@code masl check} of the same program, which the start script runs on C1 alone, against the
 * same with C2 given back ({@code -XX:TieredStopAtLevel=4} in {@code JAVA_OPTS}).
 */
final class StartUp {

    /** The kernel's clock ticks per second for {@code /proc} times (USER_HZ, 100 on Linux). */
    private static final double TICKS_PER_SECOND = 100;

    private final Path masl;
    private final Path program;
    private final Path caches;

    /** Elapsed seconds and CPU seconds of one process. */
    record Timing(double elapsed, double cpu) { }

    StartUp(Path masl, Path program) throws IOException {
        this.masl = masl;
        this.program = program;
        this.caches = Files.createTempDirectory("masl-bench-cache");
    }

    static StartUp installed() throws IOException {
        Path home = Path.of(System.getProperty("masl.bench.home", ".")).toAbsolutePath();
        Path masl = home.resolve("masl-cli/build/install/masl/bin/masl");
        if (!Files.isExecutable(masl)) {
            throw new IllegalStateException(masl + " is missing: gradle bench installs it (:masl-cli:installDist)");
        }
        return new StartUp(masl, home.resolve("missions/hello.masl"));
    }

    /** Without the cache, on the JDK's default class-data archive: masl as it was. */
    Timing before() throws Exception {
        Path jdkArchive = Path.of(System.getProperty("java.home"), "lib", "server", "classes.jsa");
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

    /** {@code masl check} of the program: on C1 alone, as the command runs it, or with C2 too. */
    Timing check(boolean withC2) throws Exception {
        return time("check", caches, withC2 ? "-XX:TieredStopAtLevel=4" : "");
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
        environment.put("JAVA_OPTS", javaOptions);
        environment.remove("MASL_OPTS");
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
