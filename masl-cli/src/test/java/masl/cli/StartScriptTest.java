package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The generated start script ({@code bin/masl}) chooses the JIT of each command: the commands that run
 * no mission get C1 alone, those that run one keep the JVM's default, and the user's own options come
 * last, so they decide; a command starts one JVM, its own (MASL_JAVA_HOME's, else JAVA_HOME's), and is
 * given the ahead-of-time cache on a JDK 25, the class-data archive on others. Run with a stand-in {@code java} that
 * prints the arguments it was given.
 */
class StartScriptTest {

    @TempDir
    Path home;
    private Path script;

    @Test
    void checkCompileAndTimelineRunWithC1Alone() throws Exception {
        for (String command : List.of("check", "compile", "timeline")) {
            List<String> jvm = javaArguments(Map.of(), command, "a.masl");
            assertTrue(jvm.contains("-XX:TieredStopAtLevel=1"), command + ": " + jvm);
        }
    }

    @Test
    void commandsThatRunMissionsOrServeKeepC2() throws Exception {
        for (String command : List.of("run", "container", "lsp")) {
            List<String> jvm = javaArguments(Map.of(), command, "a.masl");
            assertFalse(jvm.stream().anyMatch(argument -> argument.startsWith("-XX:TieredStopAtLevel")), command + ": " + jvm);
        }
    }

    @Test
    void javaOptionsComeAfterAndSoDecide() throws Exception {
        List<String> jvm = javaArguments(Map.of("JAVA_OPTS", "-XX:TieredStopAtLevel=4"), "check", "a.masl");
        assertEquals(List.of("-XX:TieredStopAtLevel=1", "-XX:TieredStopAtLevel=4"),
                jvm.stream().filter(argument -> argument.startsWith("-XX:TieredStopAtLevel")).toList());
    }

    @Test
    void theCommandAndItsArgumentsReachMainUnchanged() throws Exception {
        List<String> jvm = javaArguments(Map.of(), "check", "my program.masl");
        assertEquals(List.of("masl.cli.Main", "check", "my program.masl"), jvm.subList(jvm.size() - 3, jvm.size()));
    }

    /**
     * Debian's template asked the JVM whether it takes {@code --add-opens} with a {@code java -version}
     * of its own before every run: a second JVM, a fifth of a {@code masl run} from the cache.
     * masl needs Java 17, which takes it: the option is given, and no other JVM is started.
     */
    @Test
    void aCommandStartsOneJvmWhichOpensJavaLangAsTheTemplateDid() throws Exception {
        List<String> jvm = javaArguments(Map.of(), "run", "a.masl");
        assertEquals(List.of("started"), Files.readAllLines(home.resolve("jdk/bin/starts")));
        assertEquals("java.base/java.lang=ALL-UNNAMED", jvm.get(jvm.indexOf("--add-opens") + 1), jvm::toString);
    }

    /**
     * On a JDK 25 or later the script hands the JVM the ahead-of-time cache installing made, on others
     * (JDK 17) the class-data archive: each JDK gets what it can map, the major version read from its
     * release file.
     */
    @Test
    void aJdk25GetsTheAheadOfTimeCacheAndAJdk17TheClassDataArchive() throws Exception {
        Files.writeString(home.resolve("masl/lib/masl.aot"), "");
        Files.writeString(home.resolve("masl/lib/masl.jsa"), "");
        Path lib = home.resolve("masl/lib").toRealPath();
        releaseOf(home.resolve("jdk"), "25.0.3");
        List<String> jdk25 = javaArguments(Map.of(), "run", "a.masl");
        assertTrue(jdk25.contains("-XX:AOTCache=" + lib.resolve("masl.aot")), jdk25::toString);
        assertFalse(jdk25.stream().anyMatch(argument -> argument.startsWith("-XX:SharedArchiveFile")), jdk25::toString);
        releaseOf(home.resolve("jdk"), "17.0.15");
        List<String> jdk17 = javaArguments(Map.of(), "check", "a.masl");
        assertTrue(jdk17.contains("-XX:SharedArchiveFile=" + lib.resolve("masl.jsa")), jdk17::toString);
        assertFalse(jdk17.stream().anyMatch(argument -> argument.startsWith("-XX:AOTCache")), jdk17::toString);
    }

    /** A JDK 25 without the cache (installed where none was found) falls back to the archive, which it ignores if it must. */
    @Test
    void aJdk25WithoutTheCacheIsGivenTheArchiveAlone() throws Exception {
        Files.writeString(home.resolve("masl/lib/masl.jsa"), "");
        releaseOf(home.resolve("jdk"), "25.0.3");
        List<String> jvm = javaArguments(Map.of(), "run", "a.masl");
        assertFalse(jvm.stream().anyMatch(argument -> argument.startsWith("-XX:AOTCache")), jvm::toString);
        assertTrue(jvm.stream().anyMatch(argument -> argument.startsWith("-XX:SharedArchiveFile")), jvm::toString);
    }

    /** MASL_JAVA_HOME picks masl's JDK (a JDK 25, say) while JAVA_HOME stays the JDK of everything else. */
    @Test
    void maslJavaHomeComesBeforeJavaHome() throws Exception {
        Path jdk25 = standInJdk(home.resolve("jdk25"));
        releaseOf(jdk25, "25.0.3");
        Files.writeString(home.resolve("masl/lib/masl.aot"), "");
        List<String> jvm = javaArguments(Map.of("MASL_JAVA_HOME", jdk25.toString()), "run", "a.masl");
        assertEquals(List.of("started"), Files.readAllLines(jdk25.resolve("bin/starts")));
        assertFalse(Files.exists(home.resolve("jdk/bin/starts")));
        assertTrue(jvm.stream().anyMatch(argument -> argument.startsWith("-XX:AOTCache=")), jvm::toString);
    }

    private static void releaseOf(Path jdk, String version) throws IOException {
        Files.writeString(jdk.resolve("release"), "IMPLEMENTOR=\"Stand-in\"\nJAVA_VERSION=\"" + version + "\"\n");
    }

    /** The arguments the script gives java for {@code masl arguments...}, one per line from the stand-in. */
    private List<String> javaArguments(Map<String, String> environment, String... arguments) throws Exception {
        ProcessBuilder builder = new ProcessBuilder(script.toString());
        builder.command().addAll(List.of(arguments));
        builder.environment().put("JAVA_HOME", home.resolve("jdk").toString());
        builder.environment().remove("JAVA_OPTS");
        builder.environment().remove("MASL_OPTS");
        builder.environment().remove("MASL_JAVA_HOME");
        builder.environment().putAll(environment);
        builder.redirectErrorStream(true);
        Process process = builder.start();
        String output = new String(process.getInputStream().readAllBytes());
        assertTrue(process.waitFor(30, TimeUnit.SECONDS));
        assertEquals(0, process.exitValue(), output);
        return output.lines().toList();
    }

    /**
     * A copy of the generated script in an installation's place ({@code bin/} beside {@code lib/}), and a
     * JDK whose {@code java} notes each start in {@code starts} beside it and prints its arguments.
     */
    @BeforeEach
    void install() throws IOException {
        standInJdk(home.resolve("jdk"));
        script = home.resolve("masl/bin/masl");
        Files.createDirectories(script.getParent());
        Files.createDirectories(home.resolve("masl/lib"));
        Files.copy(Path.of(System.getProperty("masl.startScript")), script);
        Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwxr-xr-x"));
    }

    private static Path standInJdk(Path jdk) throws IOException {
        Path java = jdk.resolve("bin/java");
        Files.createDirectories(java.getParent());
        Files.writeString(java, """
                #!/bin/sh
                echo started >> "$(dirname "$0")/starts"
                for argument in "$@"; do printf '%s\\n' "$argument"; done
                """);
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"));
        return jdk;
    }
}
