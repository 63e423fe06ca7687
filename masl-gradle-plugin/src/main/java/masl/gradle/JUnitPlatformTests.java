package masl.gradle;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;
import org.gradle.api.Project;
import org.gradle.api.plugins.JavaPlugin;
import org.gradle.api.tasks.JavaExec;
import org.gradle.api.tasks.SourceSet;
import org.gradle.api.tasks.testing.Test;
import org.gradle.util.GradleVersion;

/**
 * Runs the project's tests on the JUnit Platform, the engine masl-testing brings (JUnit Jupiter) with
 * them. From Gradle 4.6 the {@code test} task does it ({@code useJUnitPlatform()}, with the platform's
 * launcher, which Gradle 9 no longer supplies). Before, {@code test} knows JUnit 4 and TestNG only: the
 * task {@code junitPlatformTest} runs the JUnit Platform's console launcher instead, as the
 * junit-platform-gradle-plugin did, and {@code test} depends on it. A build that applies that plug-in
 * itself keeps its own set-up.
 */
final class JUnitPlatformTests {

    static final String LEGACY_TASK = "junitPlatformTest";

    private JUnitPlatformTests() {
    }

    static void configure(Project project, MaslArtifacts artifacts) {
        Test test = (Test) project.getTasks().getByName(JavaPlugin.TEST_TASK_NAME);
        if (GradleVersion.current().compareTo(GradleVersion.version("4.6")) >= 0) {
            useJUnitPlatform(test);
            project.getDependencies().add(JavaPlugin.TEST_RUNTIME_ONLY_CONFIGURATION_NAME,
                    artifacts.junitPlatform("junit-platform-launcher"));
        } else if (!project.getPluginManager().hasPlugin("org.junit.platform.gradle.plugin")) {
            project.getDependencies().add(JavaPlugin.TEST_RUNTIME_ONLY_CONFIGURATION_NAME,
                    artifacts.junitPlatform("junit-platform-console"));
            JavaExec console = consoleLauncher(project);
            test.setEnabled(false);
            test.dependsOn(console);
        }
    }

    /** {@code Test.useJUnitPlatform()}, which the Gradle API of 4.4 this plug-in compiles against lacks. */
    private static void useJUnitPlatform(Test test) {
        try {
            Test.class.getMethod("useJUnitPlatform").invoke(test);
        } catch (ReflectiveOperationException absent) {
            throw new IllegalStateException("Test.useJUnitPlatform() is missing from Gradle " + GradleVersion.current().getVersion(), absent);
        }
    }

    private static JavaExec consoleLauncher(Project project) {
        SourceSet tests = ProjectModel.sourceSets(project).getByName(SourceSet.TEST_SOURCE_SET_NAME);
        JavaExec console = project.getTasks().create(LEGACY_TASK, JavaExec.class);
        console.setGroup("verification");
        console.setDescription("Runs the JUnit 5 tests on the JUnit Platform (what `test` does from Gradle 4.6)");
        console.setClasspath(tests.getRuntimeClasspath());
        MaslCommandTask.setMainClassName(console, "org.junit.platform.console.ConsoleLauncher");
        File reports = ProjectModel.buildDir(project, "test-results/junit-platform");
        String roots = tests.getOutput().getClassesDirs().getFiles().stream().map(File::getPath)
                .collect(Collectors.joining(File.pathSeparator));
        // Roots that do not exist (no Groovy tests, say) are ignored by the launcher.
        console.setArgs(List.of("execute", "--disable-banner", "--disable-ansi-colors", "--scan-class-path=" + roots, "--reports-dir=" + reports.getPath()));
        console.getInputs().files(tests.getRuntimeClasspath());
        console.getOutputs().dir(reports);
        console.onlyIf(task -> tests.getOutput().getClassesDirs().getFiles().stream().anyMatch(File::isDirectory));
        return console;
    }
}
