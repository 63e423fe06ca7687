package masl.gradle;

import java.util.ArrayList;
import java.util.List;
import org.gradle.api.GradleException;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.FileCollection;
import org.gradle.api.tasks.Internal;
import org.gradle.api.tasks.JavaExec;
import org.gradle.api.tasks.TaskAction;

/**
 * Joins a JADE platform as a container ({@code masl container}) in a JVM of its own, started in the
 * project's folder, and hosts there the bodies of the agents a run places on it and the programs of
 * those it deploys on it, until the mission ends (or, with {@code serve}, the next ones too): a robot's
 * build runs it with the robot's agent classes, which it has as {@code maslRun} has them. The program
 * comes from the run, which the container translates itself. A container that cannot join, or
 * whose mission fails, fails the task with masl's reason and exit status. Never up to date.
 */
public class MaslContainer extends JavaExec {

    private final ConfigurableFileCollection agentPath = getProject().files();
    private String container;
    private String mainHost;
    private String mainPort;
    private String localHost;
    private String secretFile;
    private String timeoutSeconds;
    private boolean serve;

    public MaslContainer() {
        MaslRun.setMainClassName(this, MaslRun.MAIN_CLASS);
        // The default secret file of a run started in the same folder is found there.
        setWorkingDir(getProject().getProjectDir());
    }

    @Internal
    public FileCollection getAgentPath() {
        return agentPath;
    }

    public void setAgentPath(Object entries) {
        agentPath.setFrom(entries);
    }

    /** The container's name, as a run's {@code --place} and {@code --deploy} name it. */
    @Internal
    public String getContainer() {
        return container;
    }

    public void setContainer(String container) {
        this.container = container;
    }

    /** The host of the platform's main container, which {@code maslRun -Pplatform=jade} starts. */
    @Internal
    public String getMainHost() {
        return mainHost;
    }

    public void setMainHost(String mainHost) {
        this.mainHost = mainHost;
    }

    @Internal
    public String getMainPort() {
        return mainPort;
    }

    public void setMainPort(String mainPort) {
        this.mainPort = mainPort;
    }

    /** This machine's address the container listens on, which the main container reaches it at (loopback unless given). */
    @Internal
    public String getLocalHost() {
        return localHost;
    }

    public void setLocalHost(String localHost) {
        this.localHost = localHost;
    }

    /** The mission's secret, as the run wrote it: the container obeys only messages signed with it. */
    @Internal
    public String getSecretFile() {
        return secretFile;
    }

    public void setSecretFile(String secretFile) {
        this.secretFile = secretFile;
    }

    /** How long to wait for the mission's end (with {@link #isServe}: each mission's). */
    @Internal
    public String getTimeoutSeconds() {
        return timeoutSeconds;
    }

    public void setTimeoutSeconds(String timeoutSeconds) {
        this.timeoutSeconds = timeoutSeconds;
    }

    /** Whether the container serves the next mission at the same address once one ended, until stopped. */
    @Internal
    public boolean isServe() {
        return serve;
    }

    public void setServe(boolean serve) {
        this.serve = serve;
    }

    /** JavaExec's action with the container's arguments, masl's failure named as such. */
    @Override
    @TaskAction
    public void exec() {
        if (container == null) {
            throw new GradleException("say which container this is with -Pcontainer=NAME, and the platform it joins"
                    + " with -PmainHost=HOST -PmainPort=PORT");
        }
        setArgs(arguments());
        MaslExit.reporting(this, super::exec, "container", container);
    }

    private List<String> arguments() {
        List<String> arguments = new ArrayList<>(List.of("container", "--name", container));
        // Without the platform's address masl refuses, saying what it needs.
        MaslRun.option(arguments, "--main-host", mainHost);
        MaslRun.option(arguments, "--main-port", mainPort);
        MaslRun.option(arguments, "--local-host", localHost);
        arguments.addAll(MaslRun.agentPathArguments(agentPath));
        MaslRun.option(arguments, "--secret-file", secretFile);
        MaslRun.option(arguments, "--timeout", timeoutSeconds);
        if (serve) {
            arguments.add("--serve");
        }
        return arguments;
    }
}
