package masl.gradle;

import static masl.gradle.UserBuild.gradle;
import static masl.gradle.UserBuild.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import org.gradle.testkit.runner.BuildResult;
import org.gradle.testkit.runner.TaskOutcome;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A user's build outside this repository that tests a mission working with a plain JADE agent: it
 * depends on the published {@code masl-testing-jade} alone, starts its own JADE agent in the platform
 * of {@code JadePlatformExtension}, and runs the mission there and in-process, copying no code of MASL.
 */
@Tag("slow")
class JadeTestingUserBuildTest {

    @TempDir
    Path project;

    @Test
    void aUsersTestRunsItsMissionInsideJadeNextToItsOwnJadeAgent() throws IOException {
        write(project.resolve("settings.gradle"), UserBuild.SETTINGS + "rootProject.name = 'greeting'\n");
        write(project.resolve("build.gradle"), UserBuild.BUILD + """
                dependencies { testImplementation 'org.masl:masl-testing-jade:%s' }
                """.formatted(UserBuild.VERSION));
        write(project.resolve("src/main/masl/Greeter.xml"), """
                <Agent short_class_name="Greeter" full_class_name="greeting.Greeter"
                       super_full_class_name="masl.agents.Default" target_language="java">
                  <Fipa agent_name="greeter" language="string"/>
                  <Primitive function_name="greet" member_id="G1" synchronous_call="true" return_type_name="java.lang.String">
                    <Parameter parameter_name="name" parameter_type="java.lang.String"/>
                  </Primitive>
                </Agent>
                """);
        write(project.resolve("src/main/masl/greet.masl"), """
                import Default.xml as Default;
                import Greeter.xml as Greeter;
                Default boss = newAgent(Default);
                Greeter doorman = newAgent(Greeter);
                scalar entry main (!(this instanceof Greeter)) { .logln(doorman.greet("team")); }
                """);
        write(project.resolve("src/main/java/greeting/Greeter.java"), """
                package greeting;
                public class Greeter extends masl.agents.Default {
                    public String greet(String name) { return "hello " + name; }
                }
                """);
        write(project.resolve("src/test/java/greeting/GreeterAgent.java"), """
                package greeting;
                import jade.core.Agent;
                import jade.core.behaviours.CyclicBehaviour;
                import jade.lang.acl.ACLMessage;
                public class GreeterAgent extends Agent {
                    @Override
                    protected void setup() {
                        addBehaviour(new CyclicBehaviour(this) {
                            @Override
                            public void action() {
                                ACLMessage request = myAgent.receive();
                                if (request == null) { block(); return; }
                                ACLMessage reply = request.createReply();
                                reply.setPerformative(ACLMessage.INFORM);
                                reply.setContent(request.getContent().replace("greet ", "hello ") + ", from JADE");
                                myAgent.send(reply);
                            }
                        });
                    }
                }
                """);
        write(project.resolve("src/test/java/greeting/GreetingTest.java"), """
                package greeting;
                import java.nio.file.Path;
                import masl.testing.MaslMission;
                import masl.testing.jade.JadePlatformExtension;
                import org.junit.jupiter.api.Test;
                import org.junit.jupiter.api.extension.RegisterExtension;
                class GreetingTest {
                    @RegisterExtension
                    static final JadePlatformExtension JADE = new JadePlatformExtension();
                    static final MaslMission GREET = MaslMission.fromFile(Path.of("src/main/masl/greet.masl"));

                    @Test
                    void inJadeTheJadeAgentAnswers() throws Exception {
                        JADE.platform().container().acceptNewAgent("greeter", new GreeterAgent()).start();
                        GREET.runOn(JADE.missionPlatform()).assertJournal("hello team, from JADE\\n");
                    }

                    @Test
                    void inProcessTheStandInAnswers() {
                        GREET.run().assertJournal("hello team\\n");
                    }
                }
                """);

        BuildResult build = gradle(project, "build").build();

        assertEquals(TaskOutcome.SUCCESS, build.task(UserBuild.JUNIT_TASK).getOutcome(), build.getOutput());
        String reports = UserBuild.testReports(project);
        assertTrue(reports.contains("tests=\"2\"") && reports.contains("failures=\"0\"") && reports.contains("errors=\"0\""),
                reports);
    }
}
