package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import masl.cli.Main;
import masl.jade.platform.JadePlatform;
import masl.jade.platform.Readiness;
import masl.missions.fipa.CalculatorAgent;
import masl.missions.fipa.GreeterAgent;
import masl.testing.jade.JadePlatformExtension;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * missions/fipa/calculator-team.masl: a MASL agent calls two plain JADE agents (CalculatorAgent, an
 * AchieveREResponder found by DF service type, JSON content; GreeterAgent, a CyclicBehaviour found by
 * name, plain string content), in the mission's JVM and in a second one (started with {@code jade.Boot},
 * as a JADE user starts agents): AGREE then INFORM and INFORM alone give results, asynchronous calls and
 * labels too; FAILURE is {@code uncaught_exception}, REFUSE and silence past the call time limit are
 * {@code timeout}; a result that is not an int is {@code uncaught_exception} and one positioned line on
 * standard error. Deployed ({@code --deploy '*=c2'}), {@code boss}'s program runs in a {@code masl
 * container} of a second JVM and calls the same agents, with the same journal; {@code calc} and
 * {@code doorman}, which the JADE agents stand for, stay in the coordinator.
 */
@Timeout(120)
@Tag("slow")
class FipaAgentsMissionTest {

    @RegisterExtension
    final JadePlatformExtension jade = new JadePlatformExtension();

    private static final String JOURNAL = """
            12 / 4 = 3
            uncaught_exception FAILURE
            1 / 0 gave 0
            timeout secret
            secret gave 0
            timeout ponder
            ponder gave 0
            uncaught_exception java.lang.IllegalStateException
            garbled gave 0
            hello team
            7 squared = 49, 5 squared = 25
            """;

    @Test
    void aMaslAgentCallsPlainJadeAgentsOfItsOwnJvm() throws Exception {
        JadePlatform platform = jade.platform();
        platform.container().acceptNewAgent("calculator-1", new CalculatorAgent()).start();
        platform.container().acceptNewAgent("greeter", new GreeterAgent()).start();
        assertMission(platform);
    }

    @Test
    void aMaslAgentCallsPlainJadeAgentsOfAnotherJvm() throws Exception {
        JadePlatform platform = jade.platform();
        try (SecondJvm peers = SecondJvm.start(jade.Boot.class, "-container", "-host", platform.host(), "-port",
                String.valueOf(platform.port()), "-local-host", "127.0.0.1", "-container-name", "peers",
                "-agents", "calculator-1:" + CalculatorAgent.class.getName() + ";greeter:" + GreeterAgent.class.getName())) {
            assertMission(platform);
        }
    }

    @Test
    void aDeployedMaslAgentCallsPlainJadeAgents(@TempDir Path folder) throws Exception {
        JadePlatform platform = jade.platform();
        platform.container().acceptNewAgent("calculator-1", new CalculatorAgent()).start();
        platform.container().acceptNewAgent("greeter", new GreeterAgent()).start();
        Path secret = folder.resolve("secret");
        try (SecondJvm c2 = SecondJvm.start(Main.class, "container", "--main-host", platform.host(), "--main-port",
                String.valueOf(platform.port()), "--name", "c2", "--timeout", "100", "--secret-file", secret.toString())) {
            assertMission(platform, "--deploy", "*=c2", "--secret-file", secret.toString());
            assertTrue(c2.output().contains("masl-ended hosted boss\n"), c2.output());
        }
    }

    private static void assertMission(JadePlatform platform, String... options) throws Exception {
        Agent probe = new Agent();
        platform.container().acceptNewAgent("probe", probe).start();
        for (String service : List.of("calculator", "greeting")) {
            assertNotNull(DFService.searchUntilFound(probe, probe.getDefaultDF(), service(service), null, 60_000),
                    service + " registered");
        }
        List<String> arguments = new ArrayList<>(List.of("run", "missions/fipa/calculator-team.masl", "--platform",
                "jade", "--main-host", platform.host(), "--main-port", String.valueOf(platform.port()), "--call-timeout",
                "500", "--timeout", "60"));
        arguments.addAll(List.of(options));
        MaslCommand run = MaslCommand.run(arguments.toArray(String[]::new));
        assertEquals(0, run.status(), run::toString);
        assertEquals(JOURNAL, run.out(), run::toString);
        String calc = "calculator-1@" + platform.platformName();
        assertEquals(Readiness.platform(platform) + "\n" + "masl: the INFORM of " + calc + " to calc.garbled:"
                + " content:1:11: error: the result of calc.garbled: expected an int, got \"many\"\n", run.err());
    }

    private static DFAgentDescription service(String type) {
        DFAgentDescription template = new DFAgentDescription();
        ServiceDescription service = new ServiceDescription();
        service.setType(type);
        template.addServices(service);
        return template;
    }
}
