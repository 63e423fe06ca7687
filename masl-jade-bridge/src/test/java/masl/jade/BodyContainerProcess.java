package masl.jade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * A second JVM running {@link BodyContainerMain} as container {@code name} of a test's platform,
 * with the test's class path and the {@code java} of {@code java.home}. {@link #close()} ends it in
 * any case (no orphan process even when the test fails).
 */
public final class BodyContainerProcess implements AutoCloseable {

    private final Process process;
    private final Path output;

    private BodyContainerProcess(Process process, Path output) {
        this.process = process;
        this.output = output;
    }

    public static BodyContainerProcess start(JadePlatform platform, String name) throws IOException {
        Path output = Files.createTempFile("masl-body-container-", ".log");
        Process process = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), BodyContainerMain.class.getName(),
                platform.host(), Integer.toString(platform.port()), name)
                .redirectErrorStream(true)
                .redirectOutput(output.toFile())
                .start();
        return new BodyContainerProcess(process, output);
    }

    /** What it printed so far. */
    public String output() throws IOException {
        return Files.readString(output);
    }

    /** Asserts that the JVM ends by itself, with status 0, within 30 s; returns what it printed. */
    public String assertEndsByItself() throws Exception {
        assertTrue(process.waitFor(30, TimeUnit.SECONDS), "the container's JVM did not end:\n" + output());
        assertEquals(0, process.exitValue(), output());
        return output();
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
