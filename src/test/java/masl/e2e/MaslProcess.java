package masl.e2e;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Function;
import masl.cli.Main;

/**
 * The {@code masl} command as a process of its own ({@code java -cp CLASSPATH masl.cli.Main …}, the
 * class path this test runs with), for what only a real process shows: signals, standard output
 * that fails, a line another JVM waits for. Its standard error is read line by line as it comes
 * ({@link #awaitErrLine}); {@link #close()} ends it in any case. A test that reads standard error as
 * the diagnostics alone runs with {@code --quiet} (no progress lines).
 */
final class MaslProcess implements AutoCloseable {

    private static final String END = new String("end of standard error");

    private final Process process;
    private final StringBuffer err = new StringBuffer();
    private final LinkedBlockingQueue<String> errLines = new LinkedBlockingQueue<>();
    private final Thread errReader;

    private MaslProcess(Process process) {
        this.process = process;
        this.errReader = new Thread(this::readErr, "masl-process-stderr");
        errReader.setDaemon(true);
        errReader.start();
    }

    /** Starts {@code masl ARGUMENTS} with standard output written to {@code out}. */
    static MaslProcess start(File out, String... arguments) throws IOException {
        return start(Map.of(), out, arguments);
    }

    /** Starts {@code masl ARGUMENTS} with {@code environment} added to this JVM's, standard output written to {@code out}. */
    static MaslProcess start(Map<String, String> environment, File out, String... arguments) throws IOException {
        return start(environment, Path.of(""), out, arguments);
    }

    /** Starts {@code masl ARGUMENTS} in the working folder {@code folder}, standard output written to {@code out}. */
    static MaslProcess startIn(Path folder, File out, String... arguments) throws IOException {
        return start(Map.of(), folder, out, arguments);
    }

    /** Starts {@code masl ARGUMENTS} with standard output appended to {@code out}, as a shell's {@code >> out} does. */
    static MaslProcess startAppendingTo(File out, String... arguments) throws IOException {
        return start(Map.of(), Path.of(""), List.of(), ProcessBuilder.Redirect.appendTo(out), arguments);
    }

    /** Starts {@code masl ARGUMENTS} in a JVM given {@code jvmOptions} ({@code -Xmx64m}), standard output written to {@code out}. */
    static MaslProcess startWith(List<String> jvmOptions, File out, String... arguments) throws IOException {
        return start(Map.of(), Path.of(""), jvmOptions, out, arguments);
    }

    private static MaslProcess start(Map<String, String> environment, Path folder, File out, String... arguments)
            throws IOException {
        return start(environment, folder, List.of(), out, arguments);
    }

    private static MaslProcess start(Map<String, String> environment, Path folder, List<String> jvmOptions, File out,
            String... arguments) throws IOException {
        return start(environment, folder, jvmOptions, ProcessBuilder.Redirect.to(out), arguments);
    }

    private static MaslProcess start(Map<String, String> environment, Path folder, List<String> jvmOptions,
            ProcessBuilder.Redirect out, String... arguments) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        command.addAll(jvmOptions);
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), Main.class.getName()));
        command.addAll(List.of(arguments));
        ProcessBuilder builder = new ProcessBuilder(command).redirectOutput(out).directory(folder.toAbsolutePath().toFile());
        builder.environment().putAll(environment);
        return new MaslProcess(builder.start());
    }

    private void readErr() {
        try (BufferedReader reader = new BufferedReader(new InputStreamReader(process.getErrorStream(),
                StandardCharsets.UTF_8))) {
            for (String line = reader.readLine(); line != null; line = reader.readLine()) {
                err.append(line).append('\n');
                errLines.add(line);
            }
        } catch (IOException closed) {
            // The process was ended: what it wrote so far is kept.
        } finally {
            errLines.add(END);
        }
    }

    Process process() {
        return process;
    }

    /**
     * Sends it SIGTERM, as {@link Process#destroy()} does, but through its {@link ProcessHandle}:
     * {@code destroy()} also closes the pipe its standard error is read from, losing what it says as it ends.
     */
    void terminate() {
        process.toHandle().destroy();
    }

    /**
     * The first line of standard error, from the next one not taken yet, that {@code reading} makes
     * something of; empty if standard error closed or {@code timeout} elapsed first.
     */
    <T> Optional<T> awaitErrLine(Function<String, Optional<T>> reading, Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (true) {
            String line = errLines.poll(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            if (line == null || line == END) {
                return Optional.empty();
            }
            Optional<T> read = reading.apply(line);
            if (read.isPresent()) {
                return read;
            }
        }
    }

    /** Waits until it ends, at most a minute, and its standard error is read; its exit status. */
    int awaitExit() throws InterruptedException {
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            throw new AssertionError("masl did not end within a minute");
        }
        errReader.join(TimeUnit.SECONDS.toMillis(60));
        return process.exitValue();
    }

    /** What it printed on standard error so far (all of it after {@link #awaitExit()}). */
    String err() {
        return err.toString();
    }

    /** What it printed on standard error, for assertion messages. */
    @Override
    public String toString() {
        return "standard error:\n" + err();
    }

    @Override
    public void close() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor(10, TimeUnit.SECONDS);
    }
}
