package masl.maven;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Collectors;
import masl.runtime.scheduling.ReplayCommand;
import masl.translator.diagnostics.MaslErrorLines;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.eclipse.aether.RepositorySystem;
import org.eclipse.aether.RepositorySystemSession;
import org.eclipse.aether.repository.RemoteRepository;

/**
 * {@code masl:run -Dmission=NAME}: runs a mission of {@code src/main/masl} with {@code masl run} in a
 * JVM of its own, started in the project's folder, after the project is compiled (the goal forks the
 * lifecycle up to {@code compile}): the journal, and only it, on standard output, as it is written;
 * masl's diagnostics and reports on standard error. A program error or a mission that does not
 * complete fails the build with masl's exit status, what it means and, for a failed mission, the
 * command that runs it again.
 */
public class RunMojo extends ProgramsMojo {

    private String mission;
    private String platform;
    private String seed;
    private String timeout;
    private String callTimeout;
    private RepositorySystem repositorySystem;
    private RepositorySystemSession repositorySession;
    private List<RemoteRepository> remoteRepositories;

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        Path program = chosenProgram();
        boolean inJade = "jade".equals(platform);
        if (!inJade && platform != null && !platform.equals("inproc")) {
            throw new MojoFailureException("unknown platform '" + platform + "': inproc (the default) or jade");
        }
        List<Path> classPath = new MaslTool(repositorySystem, repositorySession, remoteRepositories)
                .classPath(project(), plugin(), inJade, agentPath());
        String name = Programs.missionName(program);
        ReplayCommand replay = ReplayCommand.maven(name, sameRunProperties());
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)),
                // A seeded run that fails names this goal as the way to run it again.
                "-D" + ReplayCommand.PROPERTY + "=" + replay.template(),
                MaslTool.MAIN_CLASS));
        command.addAll(arguments(program, inJade));
        MaslErrorLines report = new MaslErrorLines(System.err);
        int status = run(command, report);
        if (status != 0) {
            throw new MojoFailureException(failure(name, status, report.why(), inJade ? null : replay));
        }
    }

    /** The user properties besides the mission and the seed that make a run what it was. */
    private List<String> sameRunProperties() {
        List<String> properties = new ArrayList<>();
        if (timeout != null) {
            properties.add("timeout=" + timeout);
        }
        if (callTimeout != null) {
            properties.add("callTimeout=" + callTimeout);
        }
        return properties;
    }

    private List<String> arguments(Path program, boolean inJade) {
        // Maven shows its own progress; masl's would be mixed into the journal's output otherwise.
        List<String> arguments = new ArrayList<>(List.of("run", relative(program), "--quiet"));
        String path = agentPath().stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator));
        if (!path.isEmpty()) {
            arguments.addAll(List.of("--agent-path", path));
        }
        if (inJade) {
            arguments.addAll(List.of("--platform", platform));
        }
        addOption(arguments, "--seed", seed);
        addOption(arguments, "--timeout", timeout);
        addOption(arguments, "--call-timeout", callTimeout);
        return arguments;
    }

    private static void addOption(List<String> arguments, String option, String value) {
        if (value != null) {
            arguments.addAll(List.of(option, value));
        }
    }

    /**
     * Runs masl with the journal on this JVM's standard output, as it is written, and its standard
     * error passed on to this JVM's through {@code report}, which reads why a run failed.
     */
    private int run(List<String> command, MaslErrorLines report) throws MojoExecutionException {
        Process masl;
        try {
            masl = new ProcessBuilder(command).directory(project().getBasedir())
                    .redirectInput(ProcessBuilder.Redirect.INHERIT).redirectOutput(ProcessBuilder.Redirect.INHERIT).start();
        } catch (IOException cannotStart) {
            throw new MojoExecutionException("cannot start " + command.get(0), cannotStart);
        }
        Thread errors = new Thread(() -> passOn(masl.getErrorStream(), report), "masl run's standard error");
        errors.start();
        try {
            int status = masl.waitFor();
            errors.join();
            return status;
        } catch (InterruptedException interrupted) {
            masl.destroy();
            Thread.currentThread().interrupt();
            throw new MojoExecutionException("interrupted while the mission ran", interrupted);
        }
    }

    private static void passOn(InputStream from, OutputStream to) {
        try (from) {
            from.transferTo(to);
            to.flush();
        } catch (IOException cannotPass) {
            throw new UncheckedIOException("cannot pass on masl's standard error", cannotPass);
        }
    }

    /**
     * Which mission failed, why (masl's own words), with which exit status and what it means; for a
     * mission that ran and failed, the command that runs it again (none in JADE, where no seed applies).
     */
    private String failure(String name, int status, String why, ReplayCommand replay) {
        StringBuilder message = new StringBuilder("mission ").append(name).append(" failed");
        if (!why.isEmpty()) {
            message.append(": ").append(why);
        }
        message.append(" (masl exit status ").append(status).append(": ").append(ExitStatus.meaning(status))
                .append("); masl's report is above");
        if (status != ExitStatus.MISSION_FAILED || replay == null) {
            return message.toString();
        }
        if (seed != null) {
            return message.append("\nThe same run again: ").append(replay.template().replace(ReplayCommand.SEED, seed)).toString();
        }
        return message.append("\nA run to replay: ").append(replay.template().replace(ReplayCommand.SEED, "N"))
                .append(" (any number N: one thread, every scheduling choice drawn from it)").toString();
    }

    private Path chosenProgram() throws MojoFailureException {
        List<Path> candidates = Programs.in(sourceDirectory().toPath());
        TreeSet<String> names = candidates.stream().map(Programs::missionName).collect(Collectors.toCollection(TreeSet::new));
        if (mission == null) {
            if (candidates.size() == 1) {
                return candidates.get(0);
            }
            throw new MojoFailureException("say which mission to run with -Dmission=NAME; missions: " + names);
        }
        return candidates.stream().filter(program -> Programs.missionName(program).equals(mission)).findFirst()
                .orElseThrow(() -> new MojoFailureException("no mission '" + mission + "' in " + relative(sourceDirectory().toPath())
                        + "; missions: " + names));
    }
}
