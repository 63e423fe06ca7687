package masl.maven;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
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
        Process maven = builder.start();
        if (!maven.waitFor(10, TimeUnit.MINUTES)) {
            maven.destroyForcibly();
            throw new AssertionError(name + " did not finish " + command + " in 10 minutes:\n" + Files.readString(log));
        }
        return new Result(maven.exitValue(), Files.readString(log, StandardCharsets.UTF_8));
    }

    @Override
    public String toString() {
        return name;
    }
}
