package masl.gradle;

import java.io.File;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import org.gradle.api.Plugin;
import org.gradle.api.Project;
import org.gradle.api.artifacts.Configuration;
import org.gradle.api.file.FileCollection;
import org.gradle.api.plugins.JavaPlugin;
import org.gradle.api.tasks.AbstractCopyTask;
import org.gradle.api.tasks.SourceSet;
import org.gradle.api.tasks.SourceSetContainer;

/**
 * The MASL plug-in, id {@code org.masl} (alias {@code masl}): applies {@code java}, translates the
 * MASL programs of {@code src/main/masl} (task {@code maslCompile}) and {@code src/test/masl}
 * ({@code maslCompileTest}) into Java under {@code build/generated/masl} and compiles it into the
 * source set's output, runs a mission ({@code maslRun}), hosts agents of a mission run elsewhere in a
 * JADE container ({@code maslContainer}) and runs the tests on the JUnit Platform.
 *
 * <p>A program's agent classes may be written beside it, in the same source set's Java: its
 * translation runs after that Java is compiled and checks the descriptors against the classes.
 * The project's code therefore cannot refer to the generated classes of its own source set.
 *
 * <p>Uses only API present from Gradle 4.4 to current Gradle ({@code tasks.create}, plain
 * getter/setter task properties with input/output annotations, the project read through
 * {@link ProjectModel}), and {@code GradleVersion} guards where the two differ.
 */
public class MaslPlugin implements Plugin<Project> {

    @Override
    public void apply(Project project) {
        project.getPluginManager().apply(JavaPlugin.class);
        MaslArtifacts artifacts = MaslArtifacts.ofThisPlugin();
        MaslExtension extension = project.getExtensions().create("masl", MaslExtension.class, project);
        SourceSetContainer sourceSets = ProjectModel.sourceSets(project);
        SourceSet main = sourceSets.getByName(SourceSet.MAIN_SOURCE_SET_NAME);

        // Generated code runs on the runtime and its agents extend the shipped types: both come with `agents`.
        project.getDependencies().add(JavaPlugin.IMPLEMENTATION_CONFIGURATION_NAME, artifacts.module("agents"));
        project.getDependencies().add(JavaPlugin.IMPLEMENTATION_CONFIGURATION_NAME, extension.getAgentPath());

        MaslCompile compile = translation(project, extension, main, "maslCompile");
        translation(project, extension, sourceSets.getByName(SourceSet.TEST_SOURCE_SET_NAME), "maslCompileTest");
        missionRun(project, artifacts, extension, main, compile);
        container(project, artifacts, extension, main);
        JUnitPlatformTests.configure(project, artifacts);
    }

    private static MaslCompile translation(Project project, MaslExtension extension, SourceSet sourceSet, String taskName) {
        File programs = project.file("src/" + sourceSet.getName() + "/masl");
        MaslCompile task = project.getTasks().create(taskName, MaslCompile.class);
        task.setGroup("masl");
        task.setDescription("Translates the MASL programs of " + project.relativePath(programs)
                + " to Java and compiles it, after the source set's own Java");
        task.source(programs);
        // Descriptors next to a program are inputs as much as the program: they decide how it translates.
        task.include("**/*.masl", "**/*.xml");
        task.setAgentPath(extension.getAgentPath());
        Configuration runtime = project.getConfigurations().getByName(sourceSet.getRuntimeClasspathConfigurationName());
        task.setClasspath(project.files(compiledJava(project, sourceSet), sourceSet.getCompileClasspath(), runtime));
        task.setOutputDir(ProjectModel.buildDir(project, "generated/masl/" + sourceSet.getName()));
        File classes = ProjectModel.buildDir(project, "classes/masl/" + sourceSet.getName());
        task.setClassesDir(classes);
        sourceSet.getOutput().dir(Map.<String, Object>of("builtBy", task), classes);
        // The descriptors travel with the classes they describe: the jar can be another build's agent path.
        AbstractCopyTask resources = (AbstractCopyTask) project.getTasks().getByName(sourceSet.getProcessResourcesTaskName());
        resources.from(programs, spec -> spec.include("**/*.xml"));
        return task;
    }

    /**
     * The source set's compiled Java, built by its Java compilation only: Gradle 4.4's
     * {@code output.classesDirs} is built by the {@code classes} task, which waits for maslCompile.
     */
    private static FileCollection compiledJava(Project project, SourceSet sourceSet) {
        Callable<Set<File>> folders = () -> sourceSet.getOutput().getClassesDirs().getFiles();
        return project.files(folders).builtBy(sourceSet.getCompileJavaTaskName());
    }

    private static void missionRun(Project project, MaslArtifacts artifacts, MaslExtension extension, SourceSet main,
            MaslCompile compile) {
        MaslRun run = project.getTasks().create("maslRun", MaslRun.class);
        run.setGroup("masl");
        run.setDescription("Runs a MASL mission of src/main/masl and prints its journal"
                + " (-Pmission=NAME, -Pplatform=inproc|jade, -Pseed=N, -Ptimeout=S, -PcallTimeout=MS;"
                + " with jade: -Pplace=A=C,..., -Pdeploy=A=C,..., -Pport=P, -PlocalHost=ADDRESS, -PsecretFile=F)");
        // Read when run: a build script may give maslCompile other sources (this repository's missions/ does).
        Callable<FileCollection> programs = compile::getSource;
        run.setPrograms(project.files(programs));
        run.setMission(stringProperty(project, "mission"));
        run.setPlatform(stringProperty(project, "platform"));
        run.setSeed(stringProperty(project, "seed"));
        run.setCallTimeoutMillis(stringProperty(project, "callTimeout"));
        run.setPlace(stringProperty(project, "place"));
        run.setDeploy(stringProperty(project, "deploy"));
        run.setPort(stringProperty(project, "port"));
        commandTask(project, extension, main, run, MaslTool.create(project, artifacts, "maslTool", "maslRun", run::inJade));
    }

    private static void container(Project project, MaslArtifacts artifacts, MaslExtension extension, SourceSet main) {
        MaslContainer container = project.getTasks().create("maslContainer", MaslContainer.class);
        container.setGroup("masl");
        container.setDescription("Hosts, in a JADE container, the agents a mission run elsewhere places or deploys on it"
                + " (-Pcontainer=NAME -PmainHost=H -PmainPort=P, -PlocalHost=ADDRESS, -PsecretFile=F, -Ptimeout=S, -Pserve)");
        container.setContainer(stringProperty(project, "container"));
        container.setMainHost(stringProperty(project, "mainHost"));
        container.setMainPort(stringProperty(project, "mainPort"));
        // -Pserve alone says yes, as a flag.
        String serve = stringProperty(project, "serve");
        container.setServe(serve != null && !serve.equals("false"));
        commandTask(project, extension, main, container,
                MaslTool.create(project, artifacts, "maslContainerTool", "maslContainer", () -> true));
    }

    /**
     * What every task that runs masl takes alike ({@link MaslCommandTask}): the agent path, the
     * properties {@code timeout}, {@code localHost} and {@code secretFile}, and its class path, the
     * project's classes and resources and {@code tool}, after the classes are built. The agent path
     * is given to masl as such, not as class path too; masl translates the program again, so the
     * classes maslCompile generated are not on it either.
     */
    private static void commandTask(Project project, MaslExtension extension, SourceSet main, MaslCommandTask task,
            Configuration tool) {
        task.setAgentPath(extension.getAgentPath());
        task.setTimeoutSeconds(stringProperty(project, "timeout"));
        task.setLocalHost(stringProperty(project, "localHost"));
        task.setSecretFile(stringProperty(project, "secretFile"));
        task.setClasspath(project.files(main.getOutput().getClassesDirs(), main.getOutput().getResourcesDir(), tool)
                .minus(extension.getAgentPath()));
        task.dependsOn(main.getClassesTaskName());
    }

    private static String stringProperty(Project project, String name) {
        Object value = project.findProperty(name);
        return value == null ? null : value.toString();
    }
}
