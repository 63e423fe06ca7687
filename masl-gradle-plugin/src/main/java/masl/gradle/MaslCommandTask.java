package masl.gradle;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.FileCollection;
import org.gradle.api.provider.Property;
import org.gradle.api.tasks.Internal;
import org.gradle.api.tasks.JavaExec;
import org.gradle.util.GradleVersion;

/**
 * A task that runs the {@code masl} command ({@code masl.cli.Main}) in a JVM of its own, started in
 * the project's folder, with the agent path of the build: {@code maslRun} and {@code maslContainer}.
 * What both give a JADE platform ({@code timeout}, {@code localHost}, {@code secretFile}) is here too.
 */
public abstract class MaslCommandTask extends JavaExec {

    static final String MAIN_CLASS = "masl.cli.Main";

    private final ConfigurableFileCollection agentPath = getProject().files();
    private String timeoutSeconds;
    private String localHost;
    private String secretFile;

    protected MaslCommandTask() {
        setMainClassName(this, MAIN_CLASS);
        // Names in masl's diagnostics are relative to it, as maslCompile's are; a run's secret file is there by default.
        setWorkingDir(getProject().getProjectDir());
    }

    /**
     * JavaExec's main class is {@code main} up to Gradle 6.3 (removed in 8) and the property
     * {@code mainClass} from 6.4 (absent from 4.4): each is called reflectively, so that the plug-in
     * compiles against the API of both.
     */
    @SuppressWarnings("unchecked")
    static void setMainClassName(JavaExec task, String name) {
        boolean before64 = GradleVersion.current().compareTo(GradleVersion.version("6.4")) < 0;
        try {
            if (before64) {
                JavaExec.class.getMethod("setMain", String.class).invoke(task, name);
            } else {
                ((Property<String>) JavaExec.class.getMethod("getMainClass").invoke(task)).set(name);
            }
        } catch (ReflectiveOperationException absent) {
            throw new IllegalStateException("JavaExec." + (before64 ? "setMain" : "getMainClass") + "() is missing from Gradle "
                    + GradleVersion.current().getVersion(), absent);
        }
    }

    @Internal
    public FileCollection getAgentPath() {
        return agentPath;
    }

    public void setAgentPath(Object entries) {
        agentPath.setFrom(entries);
    }

    /** A run's limit ({@code masl run --timeout}); how long a container waits for its mission's end. */
    @Internal
    public String getTimeoutSeconds() {
        return timeoutSeconds;
    }

    public void setTimeoutSeconds(String timeoutSeconds) {
        this.timeoutSeconds = timeoutSeconds;
    }

    /**
     * This machine's address the JVM's JADE container listens on and is reached at, for containers on
     * other machines ({@code --local-host}); loopback unless given.
     */
    @Internal
    public String getLocalHost() {
        return localHost;
    }

    public void setLocalHost(String localHost) {
        this.localHost = localHost;
    }

    /** The mission's secret: where a run writes it, and its containers read it ({@code --secret-file}). */
    @Internal
    public String getSecretFile() {
        return secretFile;
    }

    public void setSecretFile(String secretFile) {
        this.secretFile = secretFile;
    }

    /** {@code --agent-path} and the entries of the agent path, or nothing if it has none. */
    protected List<String> agentPathArguments() {
        String path = agentPath.getFiles().stream().map(File::getPath).collect(Collectors.joining(File.pathSeparator));
        return path.isEmpty() ? List.of() : List.of("--agent-path", path);
    }

    /** {@code option} and {@code value}, if there is a value. */
    protected static void option(List<String> arguments, String option, String value) {
        if (value != null) {
            arguments.addAll(List.of(option, value));
        }
    }
}
