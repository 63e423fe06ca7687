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
 * last, so they decide; and a command starts one JVM, its own. Run with a stand-in {@code java} that
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

    /** The arguments the script gives java for {@code masl arguments...}, one per line from the stand-in. */
    private List<String> javaArguments(Map<String, String> environment, String... arguments) throws Exception {
        ProcessBuilder builder = new ProcessBuilder(script.toString());
        builder.command().addAll(List.of(arguments));
        builder.environment().put("JAVA_HOME", home.resolve("jdk").toString());
        builder.environment().remove("JAVA_OPTS");
        builder.environment().remove("MASL_OPTS");
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
        Path java = home.resolve("jdk/bin/java");
        Files.createDirectories(java.getParent());
        Files.writeString(java, """
                #!/bin/sh
                echo started >> "$(dirname "$0")/starts"
                for argument in "$@"; do printf '%s\\n' "$argument"; done
                """);
        Files.setPosixFilePermissions(java, PosixFilePermissions.fromString("rwxr-xr-x"));
        script = home.resolve("masl/bin/masl");
        Files.createDirectories(script.getParent());
        Files.createDirectories(home.resolve("masl/lib"));
        Files.copy(Path.of(System.getProperty("masl.startScript")), script);
        Files.setPosixFilePermissions(script, PosixFilePermissions.fromString("rwxr-xr-x"));
    }
}
