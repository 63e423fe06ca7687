package masl.testing.jade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A second JVM running a main class with the test's class path and the {@code java} of
 * {@code java.home}, its standard output and error in a temporary file. {@link #close()} ends it in
 * any case (no orphan process even when the test fails) and deletes the file.
 */
public final class SecondJvm implements AutoCloseable {

    /** How long a JVM that should end by itself may take to. */
    private static final long END_WITHIN_SECONDS = 60;

    private final Process process;
    private final Path output;

    private SecondJvm(Process process, Path output) {
        this.process = process;
        this.output = output;
    }

    /** Starts {@code mainClass}'s {@code main} with {@code arguments} in a new JVM. */
    public static SecondJvm start(Class<?> mainClass, String... arguments) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-cp", System.getProperty("java.class.path"), mainClass.getName()));
        command.addAll(List.of(arguments));
        Path output = Files.createTempFile("masl-second-jvm-", ".log");
        Process process = new ProcessBuilder(command)
                .redirectErrorStream(true)
                .redirectOutput(output.toFile())
                .start();
        return new SecondJvm(process, output);
    }

    /** What it printed so far. */
    public String output() throws IOException {
        return Files.readString(output);
    }

    /** Asserts that the JVM ends by itself, with status 0, within a minute; returns what it printed. */
    public String assertEndsByItself() throws Exception {
        assertTrue(process.waitFor(END_WITHIN_SECONDS, TimeUnit.SECONDS), "the second JVM did not end:\n" + output());
        assertEquals(0, process.exitValue(), output());
        return output();
    }

    /** Waits until the JVM ends by itself, within a minute (failing the test if not); its exit status. */
    public int awaitExit() throws Exception {
        assertTrue(process.waitFor(END_WITHIN_SECONDS, TimeUnit.SECONDS), "the second JVM did not end:\n" + output());
        return process.exitValue();
    }

    /** Kills the JVM at once, as a crash would, and waits until it has ended. */
    public void kill() throws InterruptedException {
        process.destroyForcibly();
        assertTrue(process.waitFor(END_WITHIN_SECONDS, TimeUnit.SECONDS), "the second JVM did not end when killed");
    }

    @Override
    public void close() throws IOException {
        process.destroyForcibly();
        try {
            process.waitFor(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        Files.deleteIfExists(output);
    }
}
