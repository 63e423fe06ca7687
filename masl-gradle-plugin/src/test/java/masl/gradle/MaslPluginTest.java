package masl.gradle;

import static masl.gradle.UserBuild.gradle;
import static masl.gradle.UserBuild.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.gradle.testkit.runner.BuildResult;
import org.gradle.testkit.runner.TaskOutcome;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Small stand-alone builds applying the published plug-in by its id and version. */
@Tag("slow")
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
        write(project.resolve("settings.gradle"), UserBuild.SETTINGS + "rootProject.name = 'team'\n");
        write(project.resolve("build.gradle"), UserBuild.BUILD);
        write(project.resolve("src/main/masl/team.masl"), E1);
    }

    @Test
    void translatesAndCompilesThenIsUpToDateThenRebuildsAnEditedProgram() throws IOException {
        BuildResult first = gradle(project, "classes").build();
        assertEquals(TaskOutcome.SUCCESS, first.task(":maslCompile").getOutcome());
        assertTrue(Files.isRegularFile(project.resolve("build/generated/masl/main/masl/generated/team/TeamMission.java")));
        assertTrue(Files.isRegularFile(project.resolve("build/classes/masl/main/masl/generated/team/TeamMission.class")));

        BuildResult second = gradle(project, "classes").build();
        assertEquals(TaskOutcome.UP_TO_DATE, second.task(":maslCompile").getOutcome());

        Files.writeString(project.resolve("src/main/masl/team.masl"), E1.replace("team", "crew"));
        BuildResult third = gradle(project, "classes").build();
        assertEquals(TaskOutcome.SUCCESS, third.task(":maslCompile").getOutcome());
        assertTrue(generatedSources().contains("\"crew\""), "the edited program was translated again");
        assertFalse(generatedSources().contains("\"team\""), "nothing stale is left");
    }

    @Test
    void anErrorInTheProgramFailsTheBuildWithItsPosition() throws IOException {
        Files.writeString(project.resolve("src/main/masl/team.masl"), E1.replace(".logln(\"team\");", ".logln(\"team\";"));

        BuildResult result = gradle(project, "classes").buildAndFail();

        assertEquals(TaskOutcome.FAILED, result.task(":maslCompile").getOutcome());
        assertTrue(result.getOutput().contains("src/main/masl/team.masl:5:16: error: expected ')'"), result.getOutput());
    }

    @Test
    void maslRunPrintsTheJournalOfExampleE1() {
        BuildResult result = gradle(project, "-q", "maslRun", "-Pmission=team").build();

        assertEquals("Hi team\n", result.getOutput());
    }

    @Test
    void maslRunInsideJadePrintsTheSameJournal() {
        BuildResult result = gradle(project, "-q", "maslRun", "-Pmission=team", "-Pplatform=jade").build();

        // Standard error says once where the platform accepts containers (masl.jade.platform.Readiness).
        String readiness = "(?m)^masl: platform ready: host=127\\.0\\.0\\.1 port=\\d+ platform=\\S+\n";
        assertEquals("Hi team\n", result.getOutput().replaceFirst(readiness, ""), result.getOutput());
    }

    @Test
    void aMissionThatFailsFailsMaslRunSayingWhyWithWhichStatusAndHowToRunItAgain() throws IOException {
        write(project.resolve("src/main/masl/team.masl"), E1.replace(".logln(\"team\");", ".logln(\"team\" + (1 / 0));"));

        BuildResult result = gradle(project, "maslRun", "-Pseed=3", "-PcallTimeout=500").buildAndFail();

        String output = result.getOutput();
        assertTrue(output.contains("masl: the mission failed"), output);
        assertTrue(output.contains("masl: the same run again: gradle maslRun -Pmission=team -PcallTimeout=500 -Pseed=3\n"), output);
        assertTrue(output.contains("> mission team failed: the mission failed: "), output);
        assertTrue(output.contains("ArithmeticException"), output);
        assertTrue(output.contains(" (masl exit status 2: the mission failed, deadlocked, timed out or was stopped,"
                + " or its journal or trace could not be written); masl's report is above"), output);
    }

    /**
     * Inside JADE, an agent polling its own type's accessor in an empty {@code while} never parks: the
     * run still ends on its timeout, with masl's report (where each agent is) above the task's failure.
     */
    @Test
    void aJadeRunWhoseAgentSpinsEndsOnItsTimeoutWithMaslsReport() throws IOException {
        robotsAndApp("Latch", """
                package robots;
                public class Latch extends masl.agents.Default {
                    public boolean opened() { return false; }
                }
                """, """
                <Agent short_class_name="Latch" full_class_name="robots.Latch" target_language="java">
                  <Primitive function_name="opened" member_id="L1" synchronous_call="true" return_type_name="boolean.class" accessor="true">
                    <Modifier modifier_name="public"/>
                  </Primitive>
                </Agent>
                """);
        write(project.resolve("app/src/main/masl/poll.masl"), """
                import Latch.xml as Latch;
                Latch l = newAgent(Latch);
                asynchronous entry main (true) { while (!.opened()) {} }
                """);

        BuildResult result = gradle(project, ":app:maslRun", "-Pplatform=jade", "-Ptimeout=2").buildAndFail();

        String output = result.getOutput();
        assertTrue(output.contains("masl: the mission timed out\nagent l (0) at pc "), output);
        assertTrue(output.contains("(poll.masl:3: while (!.opened())): [main]\n"), output);
        assertTrue(output.contains("> mission poll failed: the mission timed out (masl exit status 2: "), output);
        assertFalse(output.contains("still alive"), output);
    }

    /**
     * Agent types of another subproject, its descriptor among the jar's resources: the jar on the
     * agent path is where the translator finds the descriptor, and the generated code the class.
     */
    @Test
    void agentTypesOfAnotherSubprojectsJarOnTheAgentPath() throws IOException {
        robotsAndApp("Greeter", """
                package robots;
                public class Greeter extends masl.agents.Default {
                    public String greeting() { return "Hi from robots"; }
                }
                """, """
                <Agent short_class_name="Greeter" full_class_name="robots.Greeter" target_language="java">
                  <Primitive function_name="greeting" member_id="G1" synchronous_call="true" return_type_name="java.lang.String">
                    <Modifier modifier_name="public"/>
                  </Primitive>
                </Agent>
                """);
        write(project.resolve("app/src/main/masl/greet.masl"), """
                import Greeter.xml as Greeter;
                Greeter g = newAgent(Greeter);
                scalar entry main (true) { .logln(.greeting()); }
                """);

        BuildResult result = gradle(project, "-q", ":app:maslRun").build();

        assertEquals("Hi from robots\n", result.getOutput());
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

    /**
     * A build of two subprojects: {@code robots}, a jar holding the agent type {@code robots.TYPE} (its
     * class and, among its resources, its descriptor), and {@code app}, the MASL programs, with that
     * jar on its agent path.
     */
    private void robotsAndApp(String type, String javaSource, String descriptor) throws IOException {
        write(project.resolve("settings.gradle"), UserBuild.SETTINGS + "rootProject.name = 'crew'\ninclude 'robots', 'app'\n");
        Files.delete(project.resolve("build.gradle"));
        write(project.resolve("robots/build.gradle"), """
                apply plugin: 'java'
                repositories { mavenLocal(); mavenCentral() }
                dependencies { implementation 'org.masl:agents:%s' }
                """.formatted(UserBuild.VERSION));
        write(project.resolve("robots/src/main/java/robots/" + type + ".java"), javaSource);
        write(project.resolve("robots/src/main/resources/" + type + ".xml"), descriptor);
        write(project.resolve("app/build.gradle"), UserBuild.BUILD + """
                masl { agentPath { project(':robots').jar } }
                """);
    }
}
