package masl.gradle;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.stream.Collectors;
import masl.cli.Masl;
import org.gradle.api.DefaultTask;
import org.gradle.api.GradleException;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.FileCollection;
import org.gradle.api.tasks.Internal;
import org.gradle.api.tasks.TaskAction;

/**
 * Runs one mission of {@code src/main/masl} as {@code masl run} does, in the build's JVM: the journal
 * goes to the build's output as it is written, and an error in the program, or a mission that
 * fails, fails the task with the command's diagnostics. Never up to date: running is the point.
 */
public class MaslRun extends DefaultTask {

    private final ConfigurableFileCollection programs = getProject().files();
    private final ConfigurableFileCollection agentPath = getProject().files();
    private String mission;
    private String platform;
    private String seed;
    private String timeoutSeconds;
    private String callTimeoutMillis;

    public MaslRun() {
        getOutputs().upToDateWhen(task -> false);
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

    @TaskAction
    public void runMission() {
        File program = chosenProgram();
        ByteArrayOutputStream diagnostics = new ByteArrayOutputStream();
        PrintStream journal = new PrintStream(new LineLogger(getLogger()), true, StandardCharsets.UTF_8);
        Thread thread = Thread.currentThread();
        ClassLoader previous = thread.getContextClassLoader();
        thread.setContextClassLoader(MaslRun.class.getClassLoader());
        int status;
        try {
            status = new Masl(journal, new PrintStream(diagnostics, true, StandardCharsets.UTF_8)).run(arguments(program));
        } finally {
            thread.setContextClassLoader(previous);
            journal.close();
        }
        String report = diagnostics.toString(StandardCharsets.UTF_8);
        if (status != 0) {
            throw new GradleException("mission " + program.getName() + " failed (masl exit status " + status + ")"
                    + (report.isEmpty() ? "" : ":\n" + report));
        }
        if (!report.isEmpty()) {
            getLogger().warn(report);
        }
    }

    private String[] arguments(File program) {
        // Absolute: the build's JVM does not run in the project's folder. Diagnostics with the
        // project-relative name come from maslCompile, which runs first.
        List<String> arguments = new ArrayList<>(List.of("run", program.getAbsolutePath()));
        String path = agentPath.getFiles().stream().map(File::getPath).collect(Collectors.joining(File.pathSeparator));
        if (!path.isEmpty()) {
            arguments.addAll(List.of("--agent-path", path));
        }
        if (platform != null && !platform.equals("inproc")) {
            arguments.addAll(List.of("--platform", platform));
        }
        if (seed != null) {
            arguments.addAll(List.of("--seed", seed));
        }
        if (timeoutSeconds != null) {
            arguments.addAll(List.of("--timeout", timeoutSeconds));
        }
        if (callTimeoutMillis != null) {
            arguments.addAll(List.of("--call-timeout", callTimeoutMillis));
        }
        return arguments.toArray(String[]::new);
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
