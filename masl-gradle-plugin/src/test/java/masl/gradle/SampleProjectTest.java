package masl.gradle;

import static masl.gradle.UserBuild.gradle;
import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.gradle.testkit.runner.BuildResult;
import org.gradle.testkit.runner.BuildTask;
import org.gradle.testkit.runner.TaskOutcome;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The sample of {@code samples/counter-team}, copied out of the checkout and built as it is, from the
 * published modules only: its agent class and descriptor beside its mission, its JUnit 5 test of the
 * mission. One build after another, as a user works with it.
 */
@Tag("slow")
class SampleProjectTest {

    private static final Path SAMPLE = Path.of(System.getProperty("masl.samples"), "counter-team");

    /** Prints every class path of the build, one line each: its name, then its entries. */
    private static final String CLASS_PATHS = """
            allprojects {
                afterEvaluate { p ->
                    p.tasks.create('printClassPaths') {
                        doLast {
                            def show = { name, files -> println "classpath $name=" + files.collect { it.path }.join('|') }
                            show('buildscript', p.buildscript.configurations.classpath.files)
                            ['compileClasspath', 'runtimeClasspath', 'testCompileClasspath', 'testRuntimeClasspath'].each {
                                show(it, p.configurations.getByName(it).files)
                            }
                            show('maslRun', p.tasks.maslRun.classpath.files)
                            show('junit', p.tasks.findByName('junitPlatformTest')?.classpath?.files ?: p.tasks.test.classpath.files)
                        }
                    }
                }
            }
            """;

    @TempDir
    Path copy;

    @Test
    void buildsTestsRunsIsUpToDateAndReportsErrorsWithTheirPositions() throws IOException {
        copySample();

        BuildResult build = gradle(copy, "build").build();
        assertEquals(TaskOutcome.SUCCESS, build.task(UserBuild.JUNIT_TASK).getOutcome());
        assertTrue(UserBuild.testReports(copy).contains("tests=\"2\"") && !UserBuild.testReports(copy).contains("failures=\"1"),
                UserBuild.testReports(copy));

        BuildResult run = gradle(copy, "-q", "maslRun", "-Pmission=count").build();
        assertEquals("total=9\n", run.getOutput());

        BuildResult again = gradle(copy, "build").build();
        List<String> notUpToDate = again.getTasks().stream()
                .filter(task -> task.getOutcome() == TaskOutcome.SUCCESS)
                .map(BuildTask::getPath).toList();
        assertEquals(List.of(), notUpToDate, again.getOutput());

        Path mission = copy.resolve("src/main/masl/count.masl");
        String program = Files.readString(mission);
        Files.writeString(mission, program.replaceFirst("total \\+= \\.click\\(\\);", "total += .click()"));
        BuildResult broken = gradle(copy, "build").buildAndFail();
        assertTrue(broken.getOutput().contains("src/main/masl/count.masl:8:26: error: expected ';'"), broken.getOutput());
        Files.writeString(mission, program);

        Path descriptor = copy.resolve("src/main/masl/Counter.xml");
        Files.writeString(descriptor, Files.readString(descriptor).replace("</Agent>", """
                  <Primitive function_name="reset" member_id="K2" synchronous_call="true" return_type_name="void">
                    <Modifier modifier_name="public"/>
                  </Primitive>
                </Agent>"""));
        BuildResult lacking = gradle(copy, "build").buildAndFail();
        assertTrue(lacking.getOutput().contains("src/main/masl/Counter.xml:7:3: error: <Primitive function_name=\"reset\">:"
                + " implementation class 'sample.Counter' has no public method void reset()"), lacking.getOutput());
    }

    @Test
    void noJarTwiceOnAnyClassPathAndNeitherJadeNorTheSimulatorUnlessAsked() throws IOException {
        copySample();
        String printer = copy.resolve("class-paths.gradle").toString();
        Files.writeString(Path.of(printer), CLASS_PATHS);

        Map<String, List<String>> inProcess = classPaths(gradle(copy, "-q", "-I", printer, "printClassPaths").build());
        Map<String, List<String>> inJade = classPaths(gradle(copy, "-q", "-I", printer, "printClassPaths", "-Pplatform=jade").build());

        assertAll(inProcess.entrySet().stream().map(path -> () -> assertEquals(List.of(), twice(path.getValue()),
                path.getKey() + " has entries twice: " + path.getValue())));
        assertAll(inProcess.entrySet().stream().map(path -> () -> assertFalse(
                path.getValue().stream().map(entry -> Path.of(entry).getFileName().toString()) // not the folders: a checkout may be named jade2
                        .anyMatch(name -> name.contains("jade") || name.contains("ode4j") || name.contains("simexecbots")),
                path.getKey() + " has JADE or the simulator: " + path.getValue())));
        List<String> jadeRun = inJade.get("maslRun");
        assertEquals(List.of(), twice(jadeRun), jadeRun.toString());
        assertTrue(jadeRun.stream().anyMatch(entry -> entry.endsWith("/jade-4.3.jar")), jadeRun.toString());
        assertTrue(jadeRun.stream().anyMatch(entry -> entry.contains("masl-jade-bridge-")), jadeRun.toString());
        assertFalse(jadeRun.stream().anyMatch(entry -> entry.contains("ode4j") || entry.contains("simexecbots")), jadeRun.toString());
    }

    private void copySample() throws IOException {
        try (Stream<Path> files = Files.walk(SAMPLE)) {
            for (Path file : files.filter(Files::isRegularFile).filter(file -> !SAMPLE.relativize(file).startsWith("build")
                    && !SAMPLE.relativize(file).startsWith(".gradle")).toList()) {
                Path target = copy.resolve(SAMPLE.relativize(file).toString());
                Files.createDirectories(target.getParent());
                Files.copy(file, target);
            }
        }
    }

    private static Map<String, List<String>> classPaths(BuildResult result) {
        return result.getOutput().lines().filter(line -> line.startsWith("classpath "))
                .map(line -> line.substring("classpath ".length()).split("=", 2))
                .collect(Collectors.toMap(parts -> parts[0], parts -> Arrays.asList(parts[1].split("\\|")),
                        (a, b) -> a, LinkedHashMap::new));
    }

    /**
     * The modules present more than once: jars by their name without the version (two versions of one
     * module are one module twice), folders by their path.
     */
    private static List<String> twice(List<String> entries) {
        Function<String, String> module = entry -> entry.endsWith(".jar")
                ? Path.of(entry).getFileName().toString().replaceFirst("-\\d[^/]*\\.jar$", "")
                : entry;
        return entries.stream().collect(Collectors.groupingBy(module, Collectors.counting())).entrySet().stream()
                .filter(counted -> counted.getValue() > 1).map(Map.Entry::getKey).sorted().toList();
    }
}
