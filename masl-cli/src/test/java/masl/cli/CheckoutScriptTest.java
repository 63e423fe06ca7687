package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The top-level {@code ./masl} of a checkout says on standard error when it is about to build the
 * command (a fresh clone: minutes of Gradle otherwise silent) or to build it again (sources changed),
 * and nothing when the command is built, which it then starts without asking Gradle. Run in a copy
 * of the script with a stand-in {@code gradle} that "builds" a command printing its arguments.
 */
class CheckoutScriptTest {

    @TempDir
    Path checkout;
    private Path bin;

    @Test
    void theFirstRunSaysItBuildsTheCommandAndTheNextOnesSayNothing() throws Exception {
        Result first = masl("--help");
        assertEquals("ran --help\n", first.out());
        assertTrue(first.err().startsWith("masl: building the command from this checkout, once: a few minutes on a"
                + " fresh clone"), first.err());
        assertEquals(1, first.err().lines().count(), first.err());
        Result second = masl("check", "a.masl");
        assertEquals(new Result("ran check a.masl\n", ""), second);
    }

    @Test
    void aChangedSourceSaysTheCommandIsBuiltAgain() throws Exception {
        masl("--help");
        Path source = checkout.resolve("masl-runtime/src/main/java/masl/runtime/Mission.java");
        Files.createDirectories(source.getParent());
        Files.writeString(source, "class Mission {}\n");
        Files.setLastModifiedTime(source, FileTime.from(Instant.now().plusSeconds(60)));
        assertEquals(new Result("ran --help\n", "masl: rebuilding the command, its sources changed (about a minute)\n"),
                masl("--help"));
    }

    @Test
    void anUnchangedCheckoutStartsTheBuiltCommandWithoutAskingGradle() throws Exception {
        masl("--help");
        assertEquals(new Result("ran check a.masl\n", ""), masl("check", "a.masl"));
        assertEquals(new Result("ran run a.masl\n", ""), masl("run", "a.masl"));
        assertEquals(List.of("build"), Files.readAllLines(checkout.resolve("gradle-calls.txt")),
                "Gradle was asked once, for the first build");
    }

    @Test
    void aSourceRemovedSinceTheBuildBuildsAgain() throws Exception {
        Path folder = checkout.resolve("masl-runtime/src/main/java/masl/runtime");
        Files.createDirectories(folder);
        Files.writeString(folder.resolve("Old.java"), "class Old {}\n");
        masl("--help");
        Files.delete(folder.resolve("Old.java"));
        Files.setLastModifiedTime(folder, FileTime.from(Instant.now().plusSeconds(60)));
        assertEquals(new Result("ran --help\n", "masl: rebuilding the command, its sources changed (about a minute)\n"),
                masl("--help"));
        assertEquals(List.of("build", "build"), Files.readAllLines(checkout.resolve("gradle-calls.txt")));
    }

    private record Result(String out, String err) {
    }

    private Result masl(String... arguments) throws IOException, InterruptedException {
        ProcessBuilder builder = new ProcessBuilder(checkout.resolve("masl").toString());
        builder.command().addAll(List.of(arguments));
        builder.environment().put("PATH", bin + ":" + System.getenv("PATH"));
        Path err = checkout.resolve("err.txt");
        builder.redirectError(err.toFile());
        Process process = builder.start();
        String out = new String(process.getInputStream().readAllBytes());
        assertTrue(process.waitFor(30, TimeUnit.SECONDS));
        assertEquals(0, process.exitValue(), () -> out + readString(err));
        return new Result(out, readString(err));
    }

    private static String readString(Path file) {
        try {
            return Files.readString(file);
        } catch (IOException unreadable) {
            throw new IllegalStateException(unreadable);
        }
    }

    /** The script and what it sources, and a {@code gradle} whose "build" writes the command's start script. */
    @BeforeEach
    void copyTheScript() throws IOException {
        Files.createDirectories(checkout.resolve("tools"));
        Files.copy(Path.of("../masl"), checkout.resolve("masl"));
        Files.copy(Path.of("../tools/ensure-gradle.sh"), checkout.resolve("tools/ensure-gradle.sh"));
        bin = checkout.resolve("stand-ins");
        Files.createDirectories(bin);
        Files.writeString(bin.resolve("gradle"), """
                #!/bin/sh
                echo build >> gradle-calls.txt
                mkdir -p masl-cli/build/install/masl/bin
                printf '#!/bin/sh\\necho ran "$@"\\n' > masl-cli/build/install/masl/bin/masl
                chmod +x masl-cli/build/install/masl/bin/masl
                """);
        Files.setPosixFilePermissions(bin.resolve("gradle"), PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.setPosixFilePermissions(checkout.resolve("masl"), PosixFilePermissions.fromString("rwxr-xr-x"));
    }
}
