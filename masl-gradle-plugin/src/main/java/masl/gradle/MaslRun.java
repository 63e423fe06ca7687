package masl.gradle;

import java.io.File;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Collectors;
import masl.runtime.scheduling.ReplayCommand;
import org.gradle.api.GradleException;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.FileCollection;
import org.gradle.api.provider.Property;
import org.gradle.api.tasks.Internal;
import org.gradle.api.tasks.JavaExec;
import org.gradle.api.tasks.TaskAction;
import org.gradle.util.GradleVersion;

/**
 * Runs one mission of {@code src/main/masl} with the {@code masl} command ({@code masl run}) in a JVM
 * of its own, started in the project's folder: the journal, and only the journal, on standard
 * output, as it is written; progress and diagnostics on standard error. The class path is the
 * configuration {@code maslTool} (masl-cli, masl-jade-bridge only for {@code platform=jade}) with the
 * project's runtime class path and compiled classes, so agent classes of the project run as they do
 * in its tests. A program error or a mission that does not complete fails the task, saying why (masl's
 * first line about it) and with which exit status; a seeded run's replay hint names this task
 * ({@link ReplayCommand#gradle}). Never up to date: running is the point.
 */
public class MaslRun extends JavaExec {

    static final String MAIN_CLASS = "masl.cli.Main";

    private final ConfigurableFileCollection programs = getProject().files();
    private final ConfigurableFileCollection agentPath = getProject().files();
    private final File projectDir = getProject().getProjectDir();
    private String mission;
    private String platform;
    private String seed;
    private String timeoutSeconds;
    private String callTimeoutMillis;
    private String place;
    private String deploy;
    private String port;
    private String localHost;
    private String secretFile;

    public MaslRun() {
        setMainClassName(this, MAIN_CLASS);
        // Program names in diagnostics are relative to it, as maslCompile's are.
        setWorkingDir(projectDir);
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
    public FileCollection getPrograms() {
        return programs;
    }

    public void setPrograms(Object files) {
        programs.setFrom(files);
    }

    @Internal
    public FileCollection getAgentPath() {
        return agentPath;
    }

    public void setAgentPath(Object entries) {
        agentPath.setFrom(entries);
    }

    /** The program's file name without {@code .masl}; may be omitted when there is one program. */
    @Internal
    public String getMission() {
        return mission;
    }

    public void setMission(String mission) {
        this.mission = mission;
    }

    /** {@code inproc} (the default) or {@code jade}. */
    @Internal
    public String getPlatform() {
        return platform;
    }

    public void setPlatform(String platform) {
        this.platform = platform;
    }

    boolean inJade() {
        return "jade".equals(platform);
    }

    @Internal
    public String getSeed() {
        return seed;
    }

    public void setSeed(String seed) {
        this.seed = seed;
    }

    @Internal
    public String getTimeoutSeconds() {
        return timeoutSeconds;
    }

    public void setTimeoutSeconds(String timeoutSeconds) {
        this.timeoutSeconds = timeoutSeconds;
    }

    @Internal
    public String getCallTimeoutMillis() {
        return callTimeoutMillis;
    }

    public void setCallTimeoutMillis(String callTimeoutMillis) {
        this.callTimeoutMillis = callTimeoutMillis;
    }

    /** {@code AGENT=CONTAINER,…}: bodies placed in other containers ({@code masl run --place}). */
    @Internal
    public String getPlace() {
        return place;
    }

    public void setPlace(String place) {
        this.place = place;
    }

    /** {@code AGENT=CONTAINER,…}: programs deployed in other containers ({@code masl run --deploy}). */
    @Internal
    public String getDeploy() {
        return deploy;
    }

    public void setDeploy(String deploy) {
        this.deploy = deploy;
    }

    /** The port of the main container the run starts, where containers join it ({@code masl run --port}). */
    @Internal
    public String getPort() {
        return port;
    }

    public void setPort(String port) {
        this.port = port;
    }

    /** This machine's address the platform listens on, for containers on other machines ({@code masl run --local-host}). */
    @Internal
    public String getLocalHost() {
        return localHost;
    }

    public void setLocalHost(String localHost) {
        this.localHost = localHost;
    }

    /** Where the run writes the mission's secret, which its containers read ({@code masl run --secret-file}). */
    @Internal
    public String getSecretFile() {
        return secretFile;
    }

    public void setSecretFile(String secretFile) {
        this.secretFile = secretFile;
    }

    /**
     * JavaExec's action, with the arguments of the mission chosen, this task as the replay hint, and
     * masl's failure named as such: why and with which exit status.
     */
    @Override
    @TaskAction
    public void exec() {
        File program = chosenProgram();
        setArgs(arguments(program));
        systemProperty(ReplayCommand.PROPERTY, ReplayCommand.gradle(missionName(program), sameRunProperties()).template());
        MaslExit.reporting(this, super::exec, "mission", missionName(program));
    }

    /** The project properties besides the mission and the seed that make a run what it was. */
    private List<String> sameRunProperties() {
        List<String> properties = new ArrayList<>();
        if (timeoutSeconds != null) {
            properties.add("timeout=" + timeoutSeconds);
        }
        if (callTimeoutMillis != null) {
            properties.add("callTimeout=" + callTimeoutMillis);
        }
        return properties;
    }

    private List<String> arguments(File program) {
        // Gradle shows its own progress; masl's would reach the build's output even under -q.
        List<String> arguments = new ArrayList<>(List.of("run", ProjectModel.relative(projectDir, program), "--quiet"));
        arguments.addAll(agentPathArguments(agentPath));
        if (inJade()) {
            arguments.addAll(List.of("--platform", platform));
        } else if (platform != null && !platform.equals("inproc")) {
            throw new GradleException("unknown platform '" + platform + "': inproc (the default) or jade");
        }
        // masl refuses the options a run would ignore (--deploy without JADE): its line says why.
        option(arguments, "--place", place);
        option(arguments, "--deploy", deploy);
        option(arguments, "--port", port);
        option(arguments, "--local-host", localHost);
        option(arguments, "--secret-file", secretFile);
        option(arguments, "--seed", seed);
        option(arguments, "--timeout", timeoutSeconds);
        option(arguments, "--call-timeout", callTimeoutMillis);
        return arguments;
    }

    /** {@code --agent-path} and the entries of {@code agentPath}, or nothing if it has none. */
    static List<String> agentPathArguments(FileCollection agentPath) {
        String path = agentPath.getFiles().stream().map(File::getPath).collect(Collectors.joining(File.pathSeparator));
        return path.isEmpty() ? List.of() : List.of("--agent-path", path);
    }

    /** {@code option} and {@code value}, if there is a value. */
    static void option(List<String> arguments, String option, String value) {
        if (value != null) {
            arguments.addAll(List.of(option, value));
        }
    }

    private File chosenProgram() {
        List<File> candidates = programs.getFiles().stream().filter(file -> file.getName().endsWith(".masl")).toList();
        TreeSet<String> names = candidates.stream().map(MaslRun::missionName).collect(Collectors.toCollection(TreeSet::new));
        if (mission == null) {
            if (candidates.size() == 1) {
                return candidates.get(0);
            }
            throw new GradleException("say which mission to run with -Pmission=NAME; missions: " + names);
        }
        return candidates.stream().filter(file -> missionName(file).equals(mission)).findFirst()
                .orElseThrow(() -> new GradleException("no mission '" + mission + "'; missions: " + names));
    }

    private static String missionName(File program) {
        return program.getName().substring(0, program.getName().length() - ".masl".length());
    }
}
