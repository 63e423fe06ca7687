package masl.maven;

import java.util.ArrayList;
import java.util.List;
import masl.translator.diagnostics.MaslErrorLines;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;
import org.eclipse.aether.RepositorySystem;
import org.eclipse.aether.RepositorySystemSession;
import org.eclipse.aether.repository.RemoteRepository;

/**
 * {@code masl:container -Dcontainer=C -DmainHost=H -DmainPort=P}: joins the JADE platform of a
 * {@code masl run} elsewhere as container C with {@code masl container} in a JVM of its own
 * ({@link MaslJvm}), after the project is compiled (the goal forks the lifecycle up to
 * {@code compile}), so that the agents a run places or deploys there ({@code masl:run -Dplace=…} or
 * {@code -Ddeploy=…}) find the project's agent classes and dependencies on its class path, with
 * JADE's. Its events and its end ({@code masl-ended hosted a,b}) on standard output; masl's
 * diagnostics on standard error. A container that ends otherwise than with its mission (or one
 * masl refuses to start) fails the build with masl's reason, its exit status and what it means.
 */
public class ContainerMojo extends MaslMojo {

    private String container;
    private String mainHost;
    private String mainPort;
    private String localHost;
    private boolean serve;
    private String secretFile;
    private String timeout;
    private RepositorySystem repositorySystem;
    private RepositorySystemSession repositorySession;
    private List<RemoteRepository> remoteRepositories;

    @Override
    public void execute() throws MojoExecutionException, MojoFailureException {
        MaslJvm masl = new MaslJvm(this, new MaslTool(repositorySystem, repositorySession, remoteRepositories), true);
        List<String> arguments = new ArrayList<>(List.of("container"));
        // masl says which of these it needs, and refuses a container without them.
        MaslJvm.addOption(arguments, "--main-host", mainHost);
        MaslJvm.addOption(arguments, "--main-port", mainPort);
        MaslJvm.addOption(arguments, "--local-host", localHost);
        MaslJvm.addOption(arguments, "--name", container);
        arguments.addAll(masl.agentPathOption());
        MaslJvm.addOption(arguments, "--timeout", timeout);
        MaslJvm.addOption(arguments, "--secret-file", secretFile);
        if (serve) {
            arguments.add("--serve");
        }
        MaslErrorLines report = new MaslErrorLines(System.err);
        int status = masl.run(List.of(), arguments, report);
        if (status != 0) {
            String what = container == null ? "container" : "container " + container;
            throw new MojoFailureException(MaslJvm.failure(what, status, report.why()).toString());
        }
    }
}
