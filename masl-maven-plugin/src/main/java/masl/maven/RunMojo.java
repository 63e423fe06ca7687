package masl.maven;

import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Collectors;
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
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)),
                MaslTool.MAIN_CLASS));
        command.addAll(arguments(program, inJade));
        int status = run(command);
        if (status != 0) {
            throw new MojoFailureException(failure(Programs.missionName(program), status, inJade));
        }
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

    /** Runs masl with this JVM's standard streams, so the journal reaches Maven's output as it is written. */
    private int run(List<String> command) throws MojoExecutionException {
        Process masl;
        try {
            masl = new ProcessBuilder(command).directory(project().getBasedir()).inheritIO().start();
        } catch (IOException cannotStart) {
            throw new MojoExecutionException("cannot start " + command.get(0), cannotStart);
        }
        try {
            return masl.waitFor();
        } catch (InterruptedException interrupted) {
            masl.destroy();
            Thread.currentThread().interrupt();
            throw new MojoExecutionException("interrupted while the mission ran", interrupted);
        }
    }

    private String failure(String name, int status, boolean inJade) {
        String failed = "mission " + name + " failed with exit status " + status + " (" + ExitStatus.meaning(status)
                + "); masl's report is above";
        if (status != ExitStatus.MISSION_FAILED || inJade) {
            return failed;
        }
        if (seed != null) {
            return failed + "\nThe same run again: mvn masl:run -Dmission=" + name + " -Dseed=" + seed;
        }
        return failed + "\nA run to replay: mvn masl:run -Dmission=" + name + " -Dseed=N (any number N: one thread,"
                + " every scheduling choice drawn from it)";
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
