package masl.e2e;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.cli.Main;

/**
 * The {@code masl} command in a child JVM (this class path, the {@code java} of {@code java.home}), its
 * standard error readable line by line as it comes, so that a test can wait for a line (readiness) while
 * the command runs. {@link #close()} ends the JVM in any case.
 */
final class MaslProcess implements AutoCloseable {

    private static final String END = new String("end of standard error");

    private final Process process;
    private final LinkedBlockingQueue<String> errLines = new LinkedBlockingQueue<>();
    private final StringBuffer out = new StringBuffer();
    private final StringBuffer err = new StringBuffer();
    private final Thread outReader;
    private final Thread errReader;

    private MaslProcess(Process process) {
        this.process = process;
        this.outReader = reader(process.getInputStream(), line -> out.append(line).append('\n'), () -> { });
        this.errReader = reader(process.getErrorStream(), line -> {
            err.append(line).append('\n');
            errLines.add(line);
        }, () -> errLines.add(END));
    }

    static MaslProcess start(String... arguments) throws IOException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java")
                .toString(), "-cp", System.getProperty("java.class.path"), Main.class.getName()));
        command.addAll(List.of(arguments));
        return new MaslProcess(new ProcessBuilder(command).start());
    }

    private static Thread reader(InputStream stream, Consumer<String> lines, Runnable atEnd) {
        Thread thread = new Thread(() -> {
            try (BufferedReader reader = new BufferedReader(new InputStreamReader(stream, StandardCharsets.UTF_8))) {
                for (String line = reader.readLine(); line != null; line = reader.readLine()) {
                    lines.accept(line);
                }
            } catch (IOException closed) {
                // The process was ended: what it wrote so far is kept.
            } finally {
                atEnd.run();
            }
        }, "masl-process-reader");
        thread.setDaemon(true);
        thread.start();
        return thread;
    }

    /**
     * The first line of standard error (from the next one not read yet) that {@code reading} makes
     * something of; empty if the process closed its standard error or {@code timeout} elapsed first.
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

    /** Waits for the process to end and its output to be read; its exit status, or -1 if it did not end in time. */
    int awaitExit(Duration timeout) throws InterruptedException {
        if (!process.waitFor(timeout.toMillis(), TimeUnit.MILLISECONDS)) {
            return -1;
        }
        outReader.join(timeout.toMillis());
        errReader.join(timeout.toMillis());
        return process.exitValue();
    }

    String out() {
        return out.toString();
    }

    String err() {
        return err.toString();
    }

    @Override
    public void close() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor(10, TimeUnit.SECONDS);
    }

    @Override
    public String toString() {
        return "stdout:\n" + out + "stderr:\n" + err;
    }
}
