package masl.maven;

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
 * JVM of its own ({@link MaslJvm}), started in the project's folder, after the project is compiled
 * (the goal forks the lifecycle up to {@code compile}): the journal, and only it, on standard output,
 * as it is written; masl's diagnostics and reports on standard error. In JADE, the mission's agents
 * may be spread over containers that {@code masl:container} (or {@code masl container}) started
 * ({@code -Dplace}, {@code -Ddeploy}, {@code -Dport}, {@code -DlocalHost}, {@code -DsecretFile},
 * passed on to masl, which says what it refuses). A program error or a mission that does not complete fails the build with
 * masl's exit status, what it means and, for a failed mission, the command that runs it again.
 */
public class RunMojo extends ProgramsMojo {

    private String mission;
    private String platform;
    private String seed;
    private String timeout;
    private String callTimeout;
    private String place;
    private String deploy;
    private String port;
    private String localHost;
    private String secretFile;
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
        MaslJvm masl = new MaslJvm(this, new MaslTool(repositorySystem, repositorySession, remoteRepositories), inJade);
        String name = Programs.missionName(program);
        ReplayCommand replay = ReplayCommand.maven(name, sameRunProperties());
        MaslErrorLines report = new MaslErrorLines(System.err);
        // A seeded run that fails names this goal as the way to run it again.
        int status = masl.run(List.of(ReplayCommand.PROPERTY + "=" + replay.template()), arguments(masl, program, inJade), report);
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

    private List<String> arguments(MaslJvm masl, Path program, boolean inJade) {
        // Maven shows its own progress; masl's would be mixed into the journal's output otherwise.
        List<String> arguments = new ArrayList<>(List.of("run", relative(program), "--quiet"));
        arguments.addAll(masl.agentPathOption());
        if (inJade) {
            arguments.addAll(List.of("--platform", platform));
        }
        MaslJvm.addOption(arguments, "--seed", seed);
        MaslJvm.addOption(arguments, "--timeout", timeout);
        MaslJvm.addOption(arguments, "--call-timeout", callTimeout);
        // Those of a mission spread over containers; masl refuses them outside JADE, and says so.
        MaslJvm.addOption(arguments, "--place", place);
        MaslJvm.addOption(arguments, "--deploy", deploy);
        MaslJvm.addOption(arguments, "--port", port);
        MaslJvm.addOption(arguments, "--local-host", localHost);
        MaslJvm.addOption(arguments, "--secret-file", secretFile);
        return arguments;
    }

    /**
     * Which mission failed, why (masl's own words), with which exit status and what it means; for a
     * mission that ran and failed, the command that runs it again (none in JADE, where no seed applies).
     */
    private String failure(String name, int status, String why, ReplayCommand replay) {
        StringBuilder message = MaslJvm.failure("mission " + name, status, why);
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
