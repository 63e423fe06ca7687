package masl.maven;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * A Maven installation the tests build users' projects with: {@code mvn} in batch mode, with the
 * modules published into build/repo of the root project as its local repository (where what it
 * fetches from Maven Central for itself stays for the next run), and the MASL version of this build.
 */
record Maven(String name, Path mvn) {

    /** Debian's Maven (package maven), which tools/ensure-maven.sh installs. */
    static Maven debian() {
        return new Maven("Debian's Maven", Path.of(System.getProperty("masl.debianMaven")));
    }

    /** The current Maven 3.9, unpacked into the build folder from Maven Central. */
    static Maven current() {
        return new Maven("Maven 3.9", Path.of(System.getProperty("masl.currentMaven")));
    }

    /** What a build printed, standard error after standard output, and its exit status. */
    record Result(int status, String output) {

        boolean succeeded() {
            return status == 0;
        }
    }

    Result run(Path project, String... goals) throws IOException, InterruptedException {
        try (Running maven = start(project, goals)) {
            return maven.await(Duration.ofMinutes(10));
        }
    }

    /** Starts a build in the background; closing it stops it, and what it started, if it still runs. */
    Running start(Path project, String... goals) throws IOException {
        if (!Files.isExecutable(mvn)) {
            throw new IllegalStateException(name + " is not installed at " + mvn + " (tools/ensure-maven.sh installs Debian's)");
        }
        List<String> command = new ArrayList<>(List.of(mvn.toString(), "--batch-mode", "--no-transfer-progress",
                "-Dmaven.repo.local=" + System.getProperty("masl.repo"), "-Dmasl.version=" + System.getProperty("masl.version")));
        command.addAll(List.of(goals));
        Path log = Files.createTempFile(project.getParent(), "mvn", ".log");
        ProcessBuilder builder = new ProcessBuilder(command).directory(project.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        builder.environment().put("JAVA_HOME", System.getProperty("java.home"));
        builder.environment().remove("MAVEN_OPTS");
        return new Running(name + " " + command, builder.start(), log);
    }

    /** A build under way, its output (standard error with standard output) in a log file. */
    record Running(String command, Process process, Path log) implements AutoCloseable {

        /** Waits for the build's end, failing if it does not end within {@code limit}. */
        Result await(Duration limit) throws IOException, InterruptedException {
            if (!process.waitFor(limit.toMillis(), TimeUnit.MILLISECONDS)) {
                close();
                throw new AssertionError(command + " did not finish in " + limit.toSeconds() + " s:\n" + output());
            }
            return new Result(process.exitValue(), output());
        }

        String output() throws IOException {
            return Files.readString(log, StandardCharsets.UTF_8);
        }

        /** Stops the JVMs the build started (masl's), then the build, if they still run. */
        @Override
        public void close() throws InterruptedException {
            List<ProcessHandle> started = process.descendants().toList();
            started.forEach(ProcessHandle::destroyForcibly);
            process.destroyForcibly();
            process.waitFor(30, TimeUnit.SECONDS);
            for (ProcessHandle child : started) {
                child.onExit().completeOnTimeout(child, 30, TimeUnit.SECONDS).join();
            }
        }
    }

    @Override
    public String toString() {
        return name;
    }
}
