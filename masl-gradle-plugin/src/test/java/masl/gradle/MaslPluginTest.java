package masl.gradle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;
import org.gradle.testkit.runner.BuildResult;
import org.gradle.testkit.runner.GradleRunner;
import org.gradle.testkit.runner.TaskOutcome;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Builds small stand-alone projects that apply the plug-in from this build's output, with the
 * installed Gradle distribution (system property {@code masl.gradleHome}) and the plug-in's class
 * path ({@code masl.pluginClasspath}), both set by this module's build script.
 */
class MaslPluginTest {

    private static final String E1 = """
            import Default.xml as Default;
            Default a, b, c = newAgent(Default);
            scalar entry main (true) {
              .log("Hi ");
              .logln("team");
            }
            """;

    @TempDir
    Path project;

    @BeforeEach
    void writeProject() throws IOException {
        Files.writeString(project.resolve("settings.gradle"), "rootProject.name = 'team'\n");
        Files.writeString(project.resolve("build.gradle"), "plugins { id 'masl' }\n");
        Files.createDirectories(project.resolve("src/main/masl"));
        Files.writeString(project.resolve("src/main/masl/team.masl"), E1);
    }

    @Test
    void translatesAndCompilesThenIsUpToDateThenRebuildsAnEditedProgram() throws IOException {
        BuildResult first = gradle("classes").build();
        assertEquals(TaskOutcome.SUCCESS, first.task(":maslCompile").getOutcome());
        assertEquals(TaskOutcome.SUCCESS, first.task(":compileJava").getOutcome());
        assertTrue(Files.isRegularFile(project.resolve("build/generated/masl/main/masl/generated/team/TeamMission.java")));
        assertTrue(Files.isRegularFile(project.resolve("build/classes/java/main/masl/generated/team/TeamMission.class")));

        BuildResult second = gradle("classes").build();
        assertEquals(TaskOutcome.UP_TO_DATE, second.task(":maslCompile").getOutcome());
        assertEquals(TaskOutcome.UP_TO_DATE, second.task(":compileJava").getOutcome());

        Files.writeString(project.resolve("src/main/masl/team.masl"), E1.replace("team", "crew"));
        BuildResult third = gradle("classes").build();
        assertEquals(TaskOutcome.SUCCESS, third.task(":maslCompile").getOutcome());
        assertTrue(generatedSources().contains("\"crew\""), "the edited program was translated again");
        assertFalse(generatedSources().contains("\"team\""), "nothing stale is left");
    }

    @Test
    void anErrorInTheProgramFailsTheBuildWithItsPosition() throws IOException {
        Files.writeString(project.resolve("src/main/masl/team.masl"), E1.replace(".logln(\"team\");", ".logln(\"team\";"));

        BuildResult result = gradle("classes").buildAndFail();

        assertEquals(TaskOutcome.FAILED, result.task(":maslCompile").getOutcome());
        assertTrue(result.getOutput().contains("src/main/masl/team.masl:5:16: error: expected ')'"), result.getOutput());
    }

    @Test
    void maslRunPrintsTheJournalOfExampleE1() {
        BuildResult result = gradle("-q", "maslRun", "-Pmission=team").build();

        assertEquals("Hi team\n", result.getOutput());
    }

    @Test
    void maslRunInsideJadePrintsTheSameJournal() {
        BuildResult result = gradle("-q", "maslRun", "-Pmission=team", "-Pplatform=jade").build();

        assertEquals("Hi team\n", result.getOutput());
    }

    private String generatedSources() throws IOException {
        try (var files = Files.walk(project.resolve("build/generated/masl/main"))) {
            StringBuilder all = new StringBuilder();
            for (Path source : files.filter(path -> path.toString().endsWith(".java")).toList()) {
                all.append(Files.readString(source));
            }
            return all.toString();
        }
    }

    private GradleRunner gradle(String... arguments) {
        List<File> pluginClasspath = Arrays.stream(System.getProperty("masl.pluginClasspath").split(File.pathSeparator))
                .map(File::new)
                .collect(Collectors.toList());
        return GradleRunner.create()
                .withGradleInstallation(new File(System.getProperty("masl.gradleHome")))
                .withProjectDir(project.toFile())
                .withPluginClasspath(pluginClasspath)
                .withArguments(arguments);
    }
}
