package masl.gradle;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.gradle.testkit.runner.GradleRunner;
import org.gradle.util.GradleVersion;

/**
 * A user's build outside this repository, run by TestKit with the installed Gradle distribution
 * (system property {@code masl.gradleHome}, set by this module's build script). It finds the plug-in
 * and MASL's modules where the README's users do, in the local Maven repository, here the folder
 * every module was just published into ({@code masl.repo}), named by {@code -Dmaven.repo.local}.
 */
final class UserBuild {

    static final String VERSION = System.getProperty("masl.version");

    /** settings.gradle of a user's build, as the README shows it. */
    static final String SETTINGS = """
            pluginManagement {
                repositories {
                    mavenLocal()
                    mavenCentral()
                }
            }
            """;

    /** build.gradle of a user's build, as the README shows it. */
    static final String BUILD = """
            plugins {
                id 'org.masl' version '%s'
            }
            repositories {
                mavenLocal()
                mavenCentral()
            }
            """.formatted(VERSION);

    /** The task that runs JUnit 5 tests on the Gradle under test. */
    static final String JUNIT_TASK = GradleVersion.current().compareTo(GradleVersion.version("4.6")) < 0
            ? ":junitPlatformTest" : ":test";

    private UserBuild() {
    }

    static GradleRunner gradle(Path project, String... arguments) {
        List<String> all = new ArrayList<>(List.of("-Dmaven.repo.local=" + System.getProperty("masl.repo")));
        all.addAll(List.of(arguments));
        return GradleRunner.create()
                .withGradleInstallation(new File(System.getProperty("masl.gradleHome")))
                .withProjectDir(project.toFile())
                .withArguments(all);
    }

    /** The JUnit XML reports of the project's tests, one after the other. */
    static String testReports(Path project) throws IOException {
        try (Stream<Path> files = Files.walk(project.resolve("build/test-results"))) {
            StringBuilder all = new StringBuilder();
            for (Path report : files.filter(file -> file.getFileName().toString().endsWith(".xml")).toList()) {
                all.append(Files.readString(report));
            }
            return all.toString();
        }
    }

    static void write(Path file, String text) throws IOException {
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
    }
}
