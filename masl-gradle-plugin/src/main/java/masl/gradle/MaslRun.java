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
import org.gradle.api.tasks.Internal;
import org.gradle.api.tasks.TaskAction;

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
public class MaslRun extends MaslCommandTask {

    private final ConfigurableFileCollection programs = getProject().files();
    private final File projectDir = getProject().getProjectDir();
    private String mission;
    private String platform;
    private String seed;
    private String callTimeoutMillis;
    private String place;
    private String deploy;
    private String port;

    @Internal
    public FileCollection getPrograms() {
        return programs;
    }

    public void setPrograms(Object files) {
        programs.setFrom(files);
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
        if (getTimeoutSeconds() != null) {
            properties.add("timeout=" + getTimeoutSeconds());
        }
        if (callTimeoutMillis != null) {
            properties.add("callTimeout=" + callTimeoutMillis);
        }
        return properties;
    }

    private List<String> arguments(File program) {
        // Gradle shows its own progress; masl's would reach the build's output even under -q.
        List<String> arguments = new ArrayList<>(List.of("run", ProjectModel.relative(projectDir, program), "--quiet"));
        arguments.addAll(agentPathArguments());
        if (inJade()) {
            arguments.addAll(List.of("--platform", platform));
        } else if (platform != null && !platform.equals("inproc")) {
            throw new GradleException("unknown platform '" + platform + "': inproc (the default) or jade");
        }
        // masl refuses the options a run would ignore (--deploy without JADE): its line says why.
        option(arguments, "--place", place);
        option(arguments, "--deploy", deploy);
        option(arguments, "--port", port);
        option(arguments, "--local-host", getLocalHost());
        option(arguments, "--secret-file", getSecretFile());
        option(arguments, "--seed", seed);
        option(arguments, "--timeout", getTimeoutSeconds());
        option(arguments, "--call-timeout", callTimeoutMillis);
        return arguments;
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
