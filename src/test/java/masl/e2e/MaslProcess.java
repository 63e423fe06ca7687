package masl.e2e;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import masl.cli.Main;

/**
 * The {@code masl} command as a process of its own ({@code java -cp CLASSPATH masl.cli.Main …}, the
 * class path this test runs with), for what only a real process shows: signals, standard output
 * that fails. Its standard error goes to a file; {@link #close()} ends it in any case. A test that
 * reads standard error as the diagnostics alone runs with {@code --quiet} (no progress lines).
 */
final class MaslProcess implements AutoCloseable {

    private final Process process;
    private final Path err;

    private MaslProcess(Process process, Path err) {
        this.process = process;
        this.err = err;
    }

    /** Starts {@code masl ARGUMENTS} with standard output written to {@code out}. */
    static MaslProcess start(File out, String... arguments) throws IOException {
        return start(Map.of(), out, arguments);
    }

    /** Starts {@code masl ARGUMENTS} with {@code environment} added to this JVM's, standard output written to {@code out}. */
    static MaslProcess start(Map<String, String> environment, File out, String... arguments) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), Main.class.getName()));
        command.addAll(List.of(arguments));
        Path err = Files.createTempFile("masl-stderr-", ".txt");
        ProcessBuilder builder = new ProcessBuilder(command).redirectOutput(out).redirectError(err.toFile());
        builder.environment().putAll(environment);
        Process process = builder.start();
        return new MaslProcess(process, err);
    }

    Process process() {
        return process;
    }

    /** Waits until it ends, at most a minute; its exit status. */
    int awaitExit() throws InterruptedException {
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            throw new AssertionError("masl did not end within a minute");
        }
        return process.exitValue();
    }

    String err() throws IOException {
        return Files.readString(err);
    }

    /** What it printed on standard error, for assertion messages. */
    @Override
    public String toString() {
        try {
            return "standard error:\n" + err();
        } catch (IOException unreadable) {
            return "standard error unreadable: " + unreadable;
        }
    }

    @Override
    public void close() throws IOException {
        process.destroyForcibly();
        try {
            process.waitFor(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        Files.deleteIfExists(err);
    }
}
