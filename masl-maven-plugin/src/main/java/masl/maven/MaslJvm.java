package masl.maven;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import masl.translator.diagnostics.MaslErrorLines;
import org.apache.maven.plugin.MojoExecutionException;

/**
 * The {@code masl} command in a JVM of its own, started in the project's folder on the class path of
 * {@link MaslTool}: its standard output is the build's, as it is written; its standard error is
 * passed on to the build's and read on the way for why it failed ({@link MaslErrorLines}). What
 * {@code masl:run} and {@code masl:container} share. If Maven's JVM ends first (stopped), masl is
 * stopped with it rather than left behind.
 */
final class MaslJvm {

    private final MaslMojo mojo;
    private final List<Path> classPath;

    /** masl with the project's runtime class path, and JADE ({@code masl-jade-bridge}) if {@code inJade}. */
    MaslJvm(MaslMojo mojo, MaslTool tool, boolean inJade) throws MojoExecutionException {
        this.mojo = mojo;
        this.classPath = tool.classPath(mojo.project(), mojo.plugin(), inJade, mojo.agentPath());
    }

    /** {@code --agent-path} with the goal's agent path, as masl takes it; nothing when it is empty. */
    List<String> agentPathOption() {
        String path = mojo.agentPath().stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator));
        return path.isEmpty() ? List.of() : List.of("--agent-path", path);
    }

    /** Adds {@code option value} to {@code arguments} when the value was given. */
    static void addOption(List<String> arguments, String option, String value) {
        if (value != null) {
            arguments.addAll(List.of(option, value));
        }
    }

    /**
     * Runs {@code masl ARGUMENTS} with these system properties ({@code -Dname=value}) until it ends, its
     * standard error through {@code report}.
     *
     * @return masl's exit status
     */
    int run(List<String> systemProperties, List<String> arguments, MaslErrorLines report) throws MojoExecutionException {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator))));
        systemProperties.forEach(property -> command.add("-D" + property));
        command.add(MaslTool.MAIN_CLASS);
        command.addAll(arguments);
        Process masl;
        try {
            masl = new ProcessBuilder(command).directory(mojo.project().getBasedir())
                    .redirectInput(ProcessBuilder.Redirect.INHERIT).redirectOutput(ProcessBuilder.Redirect.INHERIT).start();
        } catch (IOException cannotStart) {
            throw new MojoExecutionException("cannot start " + command.get(0), cannotStart);
        }
        Thread stopWithMaven = new Thread(masl::destroy, "stops masl " + arguments.get(0) + " with Maven");
        Runtime.getRuntime().addShutdownHook(stopWithMaven);
        Thread errors = new Thread(() -> passOn(masl.getErrorStream(), report), "masl " + arguments.get(0) + "'s standard error");
        errors.start();
        try {
            int status = masl.waitFor();
            errors.join();
            return status;
        } catch (InterruptedException interrupted) {
            masl.destroy();
            Thread.currentThread().interrupt();
            throw new MojoExecutionException("interrupted while masl " + arguments.get(0) + " ran", interrupted);
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(stopWithMaven);
            } catch (IllegalStateException shuttingDown) {
                // Maven's JVM is ending: the hook stops masl.
            }
        }
    }

    /**
     * The message of a goal that masl failed: what failed ({@code mission count}, {@code container c2}),
     * why (masl's own words, if it said any), with which exit status and what it means.
     */
    static StringBuilder failure(String what, int status, String why) {
        StringBuilder message = new StringBuilder(what).append(" failed");
        if (!why.isEmpty()) {
            message.append(": ").append(why);
        }
        return message.append(" (masl exit status ").append(status).append(": ").append(ExitStatus.meaning(status))
                .append("); masl's report is above");
    }

    private static void passOn(InputStream from, OutputStream to) {
        try (from) {
            from.transferTo(to);
            to.flush();
        } catch (IOException cannotPass) {
            throw new UncheckedIOException("cannot pass on masl's standard error", cannotPass);
        }
    }
}
