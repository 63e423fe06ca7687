package masl.gradle;

import java.util.ArrayList;
import java.util.List;
import org.gradle.api.GradleException;
import org.gradle.api.tasks.Internal;
import org.gradle.api.tasks.TaskAction;

/**
 * Joins a JADE platform as a container ({@code masl container}) in a JVM of its own, started in the
 * project's folder, and hosts there the bodies of the agents a run places on it and the programs of
 * those it deploys on it, until the mission ends (or, with {@code serve}, the next ones too): a robot's
 * build runs it with the robot's agent classes, which it has as {@code maslRun} has them. The program
 * comes from the run, which the container translates itself. A container that cannot join, or
 * whose mission fails, fails the task with masl's reason and exit status. Never up to date.
 */
public class MaslContainer extends MaslCommandTask {

    private String container;
    private String mainHost;
    private String mainPort;
    private boolean serve;

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
        option(arguments, "--main-host", mainHost);
        option(arguments, "--main-port", mainPort);
        option(arguments, "--local-host", getLocalHost());
        arguments.addAll(agentPathArguments());
        option(arguments, "--secret-file", getSecretFile());
        option(arguments, "--timeout", getTimeoutSeconds());
        if (serve) {
            arguments.add("--serve");
        }
        return arguments;
    }
}
