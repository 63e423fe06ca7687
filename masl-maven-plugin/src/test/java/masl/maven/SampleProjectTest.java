package masl.maven;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Duration;
import java.util.List;
import java.util.jar.JarFile;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * samples/counter-team-maven, copied out of the checkout and built as it is by Debian's Maven and by a
 * current Maven 3.9, with the plug-in and the modules published by this build: on each, the missions
 * translated and compiled with the project's agent class and its JUnit tests green (and the jar made,
 * with Maven 3.9), then a {@code masl:run} in the same build: seeded, of the mission printing its
 * journal (Maven 3.9, which then runs it in JADE too) or of a mission that fails, failing with its
 * status and the command that replays it (Debian's); an error in a mission and in a descriptor failing
 * {@code masl:check} at their positions; one in a mission of the tests failing the build before any
 * test runs; a robot's copy of the sample serving a container ({@code masl:container}) to which the
 * base station's copy deploys the mission's agents ({@code masl:run -Ddeploy}), and a deployment
 * outside JADE failing with masl's refusal. Few builds per Maven: each costs seconds of JVM start and
 * of Maven's own plug-ins.
 */
@Tag("slow")
class SampleProjectTest {

    static List<Maven> mavens() {
        return List.of(Maven.debian(), Maven.current());
    }

    @Test
    void currentMavenTestsTheMissionThenRunsItWithASeedAndInJade(@TempDir Path folder) throws Exception {
        Path project = sample(folder);

        Maven.Result build = Maven.current().run(project, "verify", "masl:run", "-Dmission=count", "-Dseed=3");

        assertTrue(build.succeeded(), build.output());
        assertTestsPassed(project, build);
        assertTrue(build.output().lines().anyMatch("total=9"::equals), "the journal of masl:run:\n" + build.output());
        try (JarFile jar = new JarFile(project.resolve("target/counter-team-1.0.jar").toFile())) {
            assertTrue(jar.getEntry("Counter.xml") != null && jar.getEntry("sample/Counter.class") != null,
                    "the descriptor in the jar beside its class, so the jar can be an agent path");
        }

        Maven.Result inJade = Maven.current().run(project, "masl:run", "-Dmission=count", "-Dplatform=jade", "-Dtimeout=60");

        assertTrue(inJade.succeeded(), inJade.output());
        assertTrue(inJade.output().lines().anyMatch("total=9"::equals), "the journal of masl:run in JADE:\n" + inJade.output());
    }

    @Test
    void debianMavenTestsTheMissionThenAFailedRunNamesItsStatusAndTheCommandThatReplaysIt(@TempDir Path folder) throws Exception {
        Path project = sample(folder);
        Files.writeString(project.resolve("src/main/masl/crash.masl"), """
                import Default.xml as Default;
                Default a = newAgent(Default);
                scalar entry main (true) {
                    local int zero = 0;
                    .logln("half=" + (1 / zero));
                }
                """);

        Maven.Result build = Maven.debian().run(project, "test", "masl:run", "-Dmission=crash", "-Dseed=5");

        assertEquals(1, build.status(), build.output());
        assertTestsPassed(project, build);
        String output = build.output();
        assertTrue(output.contains("caused by java.lang.ArithmeticException: / by zero"), "masl's report:\n" + output);
        assertTrue(output.contains("masl: the same run again: mvn masl:run -Dmission=crash -Dseed=5\n"), "masl's replay hint:\n" + output);
        assertTrue(output.contains("mission crash failed: the mission failed: java.lang.IllegalStateException: agent a (0) at pc 2"
                + " (crash.masl:5: .logln(\"half=\" + (1 / zero));) failed (masl exit status 2: the mission failed, deadlocked, timed out"
                + " or was stopped, or its journal or trace could not be written); masl's report is above\n"
                + "[ERROR] The same run again: mvn masl:run -Dmission=crash -Dseed=5\n"), output);
    }

    @Test
    void aMistakeInAMissionOfTheTestsFailsTheBuildAtItsPositionBeforeAnyTestRuns(@TempDir Path folder) throws Exception {
        Path project = sample(folder);
        Path mission = project.resolve("src/test/masl/click.masl");
        Files.writeString(mission, Files.readString(mission).replace(".click());\n}", ".clack());\n}"));

        Maven.Result build = Maven.current().run(project, "test");

        assertEquals(1, build.status(), build.output());
        String output = build.output();
        assertTrue(output.contains("masl-maven-plugin:0.1.0:testCompile"), output);
        assertTrue(output.lines().anyMatch(line -> line.matches("\\[ERROR\\] src/test/masl/click\\.masl:7:2[45]: error: .*clack.*")), output);
        assertFalse(output.contains("T E S T S"), "no test runs:\n" + output);
        assertTrue(Files.isDirectory(project.resolve("target/classes/masl/generated/count")), "the main code compiled first");
    }

    @Test
    void aRobotsBuildServesAContainerTheBaseStationsRunDeploysTheMissionsAgentsTo(@TempDir Path folder) throws Exception {
        // Two copies, two builds: the robot's hosts the agents, the base station's runs the mission.
        Path robot = sample(folder.resolve("robot"));
        Path station = sample(folder.resolve("station"));
        int port = freePort();
        String secret = "-DsecretFile=" + folder.resolve("mission-secret");

        try (Maven.Running container = Maven.current().start(robot, "-q", "masl:container", "-Dcontainer=c2", "-DmainHost=127.0.0.1",
                "-DmainPort=" + port, "-Dtimeout=300", secret)) {
            Maven.Result run = Maven.current().run(station, "-q", "masl:run", "-Dmission=count", "-Dplatform=jade", "-Dport=" + port,
                    "-Ddeploy=*=c2", "-Dtimeout=120", secret);
            Maven.Result hosted = container.await(Duration.ofMinutes(2));

            assertEquals(0, run.status(), run.output() + "\nthe container's build:\n" + hosted.output());
            assertTrue(run.output().lines().anyMatch("total=9"::equals), "the journal of masl:run:\n" + run.output());
            assertEquals(0, hosted.status(), hosted.output());
            assertTrue(hosted.output().lines().anyMatch("masl-ended hosted a,b,c"::equals), "the container's output:\n" + hosted.output());
        }
    }

    @Test
    void aDeploymentOutsideJadeFailsTheBuildWithMaslsRefusal(@TempDir Path folder) throws Exception {
        Path project = sample(folder);

        Maven.Result run = Maven.debian().run(project, "masl:run", "-Dmission=count", "-Ddeploy=*=c2");

        assertEquals(1, run.status(), run.output());
        String refusal = "--place, --deploy, --port, --local-host and --secret-file are for a JADE platform: give them with"
                + " --platform jade";
        assertTrue(run.output().lines().anyMatch(("masl: " + refusal)::equals), "masl's line, passed on:\n" + run.output());
        assertTrue(run.output().contains("mission count failed: " + refusal
                + " (masl exit status 64: masl was called wrongly); masl's report is above"), run.output());
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0)) {
            return socket.getLocalPort();
        }
    }

    /** The missions translated and compiled with the project's agent class, and the JUnit test of count green. */
    private static void assertTestsPassed(Path project, Maven.Result build) throws IOException {
        assertTrue(build.output().contains("Tests run: 3, Failures: 0, Errors: 0, Skipped: 0"), build.output());
        try (Stream<Path> generated = Files.list(project.resolve("target/generated-sources/masl/masl/generated/count"))) {
            assertTrue(generated.anyMatch(file -> file.toString().endsWith(".java")), "the mission's Java in its source root");
        }
        try (Stream<Path> generated = Files.list(project.resolve("target/generated-test-sources/masl/masl/generated/click"))) {
            assertTrue(generated.anyMatch(file -> file.toString().endsWith(".java")), "the tests' mission's Java in the test source root");
        }
        try (Stream<Path> compiled = Files.list(project.resolve("target/test-classes/masl/generated/click"))) {
            assertTrue(compiled.anyMatch(file -> file.toString().endsWith(".class")), "the tests' mission compiled with the tests");
        }
        assertTrue(Files.isRegularFile(project.resolve("target/classes/Counter.xml")), "the descriptor beside its class");
    }

    @ParameterizedTest
    @MethodSource("mavens")
    void errorsInAMissionAndInADescriptorFailCheckAtTheirPositions(Maven maven, @TempDir Path folder) throws Exception {
        Path project = sample(folder);
        Path mission = project.resolve("src/main/masl/count.masl");
        Files.writeString(mission, Files.readString(mission).replace(".logln(\"total=\" + total);", ".logln(\"total=\" + total;"));
        Path descriptor = project.resolve("src/main/masl/Counter.xml");
        Files.writeString(descriptor, Files.readString(descriptor).replace("</Agent>", """
                  <Primitive function_name="reset" member_id="K2" synchronous_call="true" return_type_name="void.class">
                    <Modifier modifier_name="public"/>
                  </Primitive>
                </Agent>"""));
        Files.writeString(project.resolve("src/main/masl/tally.masl"), """
                import Counter.xml as Counter;
                Counter a = newAgent(Counter);
                scalar entry main (true) {
                    .logln("clicks=" + .click());
                }
                """);

        Maven.Result check = maven.run(project, "masl:check");

        assertEquals(1, check.status(), check.output());
        String output = check.output();
        assertTrue(output.contains("""
                [ERROR] src/main/masl/count.masl:13:32: error: expected ')'
                [ERROR]         .logln("total=" + total;
                [ERROR]                                ^
                """), output);
        assertTrue(output.contains("src/main/masl/Counter.xml:7:3: error: <Primitive function_name=\"reset\">:"
                + " implementation class 'sample.Counter' has no public method void reset()"), output);
        assertFalse(Files.exists(project.resolve("target/generated-sources")), "masl:check generates nothing");
    }

    /** The sample, copied out of the checkout, as a user would start from it. */
    private static Path sample(Path folder) throws IOException {
        Path source = Path.of(System.getProperty("masl.samples"), "counter-team-maven");
        Path copy = folder.resolve("counter-team");
        try (Stream<Path> files = Files.walk(source)) {
            // Not what a build of the sample in the checkout may have left in target/.
            for (Path file : files.filter(file -> !source.relativize(file).startsWith("target")).toList()) {
                Path target = copy.resolve(source.relativize(file).toString());
                if (Files.isDirectory(file)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(file, target, StandardCopyOption.COPY_ATTRIBUTES);
                }
            }
        }
        return copy;
    }
}
