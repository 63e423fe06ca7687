package masl.gradle;

import java.io.File;
import java.util.List;
import masl.translator.MaslClassPath;
import org.gradle.api.Plugin;
import org.gradle.api.Project;
import org.gradle.api.plugins.JavaPlugin;
import org.gradle.api.tasks.SourceSet;
import org.gradle.api.tasks.SourceSetContainer;
import org.gradle.api.tasks.compile.JavaCompile;

/**
 * The {@code masl} plug-in: applies {@code java}, translates the MASL programs of
 * {@code src/main/masl} (task {@code maslCompile}) and {@code src/test/masl} ({@code maslCompileTest})
 * into Java under {@code build/generated/masl}, compiled with the source set's Java, and runs a
 * mission ({@code maslRun}).
 *
 * <p>Uses only API present from Gradle 4.4 to current Gradle: {@code Project.property("sourceSets")}
 * rather than the Java convention object, {@code tasks.create}, and plain getter/setter task
 * properties with input/output annotations.
 */
public class MaslPlugin implements Plugin<Project> {

    @Override
    public void apply(Project project) {
        project.getPluginManager().apply(JavaPlugin.class);
        MaslExtension extension = project.getExtensions().create("masl", MaslExtension.class, project);
        SourceSetContainer sourceSets = (SourceSetContainer) project.property("sourceSets");

        MaslCompile main = translation(project, extension, sourceSets.getByName(SourceSet.MAIN_SOURCE_SET_NAME), "maslCompile");
        translation(project, extension, sourceSets.getByName(SourceSet.TEST_SOURCE_SET_NAME), "maslCompileTest");

        // Generated code is compiled against the runtime and the agents' classes, and runs with them.
        project.getDependencies().add("implementation", project.files(MaslClassPath.runtimeAndShippedAgents()));
        project.getDependencies().add("implementation", extension.getAgentPath());

        MaslRun run = project.getTasks().create("maslRun", MaslRun.class);
        run.setGroup("masl");
        run.setDescription("Runs a MASL mission of src/main/masl and prints its journal (-Pmission=NAME, -Pplatform=inproc|jade, -Ptimeout=S, -PcallTimeout=MS)");
        run.setPrograms(main.getSource());
        run.setAgentPath(extension.getAgentPath());
        run.setMission(stringProperty(project, "mission"));
        run.setPlatform(stringProperty(project, "platform"));
        run.setSeed(stringProperty(project, "seed"));
        run.setTimeoutSeconds(stringProperty(project, "timeout"));
        run.setCallTimeoutMillis(stringProperty(project, "callTimeout"));
        run.dependsOn(main);
    }

    private static MaslCompile translation(Project project, MaslExtension extension, SourceSet sourceSet, String taskName) {
        File programs = project.file("src/" + sourceSet.getName() + "/masl");
        File generated = new File(project.getBuildDir(), "generated/masl/" + sourceSet.getName());
        MaslCompile task = project.getTasks().create(taskName, MaslCompile.class);
        task.setGroup("masl");
        task.setDescription("Translates the MASL programs of " + project.relativePath(programs) + " to Java");
        task.source(programs);
        // Descriptors next to a program are inputs as much as the program: they decide how it translates.
        task.include("**/*.masl", "**/*.xml");
        task.setAgentPath(extension.getAgentPath());
        task.setOutputDir(generated);
        sourceSet.getJava().srcDir(generated);
        JavaCompile compile = (JavaCompile) project.getTasks().getByName(sourceSet.getCompileJavaTaskName());
        compile.dependsOn(task);
        // Generated code is Java 17, like the runtime it runs on.
        if (!compile.getOptions().getCompilerArgs().contains("--release")) {
            compile.getOptions().getCompilerArgs().addAll(List.of("--release", "17"));
        }
        return task;
    }

    private static String stringProperty(Project project, String name) {
        Object value = project.findProperty(name);
        return value == null ? null : value.toString();
    }
}
