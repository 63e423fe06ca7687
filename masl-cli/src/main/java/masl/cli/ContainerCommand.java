package masl.cli;

import java.io.PrintStream;
import java.nio.file.Path;
import java.time.Duration;
import masl.jade.placement.MaslContainer;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.trust.MissionSecret;
import masl.jade.trust.SecretFile;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.DescriptorLoader;

/**
 * {@code masl container --main-host H --main-port P --name C}: joins a JADE platform as container
 * {@code C}, hosts the bodies of the agents that a {@code masl run --platform jade --place …} places
 * on it (their implementations' primitives run here, their programs in the coordinator's JVM), runs
 * the programs of those a {@code --deploy …} deploys on it (translated here, {@link ContainerTranslator}),
 * and ends when the coordinator says the mission ended. The main container may start later: it is
 * waited for for {@value #JOIN_SECONDS} s. Standard output shows each shared event the coordinator
 * sends ({@code masl-event {"event": …}}) and, at the end, the bodies hosted
 * ({@code masl-ended hosted b,d}); standard error, once the bodies are placed, the line
 * {@code masl: container ready: name=C host=H port=P platform=… agents=b,d} ({@link masl.jade.platform.Readiness}); exit 0 once the mission ended, 2 if {@code --timeout} elapsed first, the
 * platform cannot be joined, or the coordinator or the main container disappeared (noticed within a second), or the platform shut
 * down, whether or not bodies were placed here.
 * It obeys only the platform's coordinator, and only messages signed with the secret {@code masl run}
 * wrote to {@code --secret-file} (read when the coordinator first writes); each message refused is one
 * line on standard error.
 */
final class ContainerCommand {

    private static final long JOIN_SECONDS = 30;
    private static final Duration NO_TIMEOUT = Duration.ofDays(3650);

    private final PrintStream out;
    private final PrintStream err;

    ContainerCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    int run(CommandLine line) throws UsageException {
        if (line.mainHost == null || line.mainPort == null || line.containerName == null) {
            throw new UsageException("masl container needs --main-host, --main-port and --name");
        }
        if (!line.operands.isEmpty()) {
            throw new UsageException("masl container takes no operand: descriptors and classes come from --agent-path");
        }
        DescriptorLoader descriptors = new DescriptorLoader(AgentPath.parse(line.agentPath));
        Duration timeout = line.timeoutSeconds == null ? NO_TIMEOUT : Duration.ofSeconds(line.timeoutSeconds);
        long deadline = System.nanoTime() + timeout.toNanos();
        try (ContainerTranslator translator = new ContainerTranslator(AgentPath.parse(line.agentPath));
                MaslContainer container = join(line, descriptors, translator)) {
            if (container.awaitBodies(timeout)) {
                err.println(container.readiness());
                err.flush();
            }
            boolean ended = container.awaitMissionEnd(Duration.ofNanos(Math.max(0, deadline - System.nanoTime())));
            if (!ended) {
                err.println("masl: container " + line.containerName + ": no mission ended within " + timeout.toSeconds()
                        + " s");
                return Masl.MISSION_FAILED;
            }
            if (container.unhosted().isPresent()) {
                err.println("masl: " + container.unhosted().get());
                return Masl.MISSION_FAILED;
            }
            if (container.lostPlatform().isPresent()) {
                err.println("masl: container " + line.containerName + ": " + container.lostPlatform().get()
                        + (container.hostedAgents().isEmpty() ? "" : "; its agents were stopped"));
                return Masl.MISSION_FAILED;
            }
            out.println("masl-ended hosted " + String.join(",", container.hostedAgents()));
            return Masl.OK;
        } catch (JadeException cannotJoin) {
            err.println("masl: container " + line.containerName + ": " + cannotJoin.getMessage());
            return Masl.MISSION_FAILED;
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            return Masl.MISSION_FAILED;
        } finally {
            out.flush();
        }
    }

    /**
     * Joins, retrying for {@value #JOIN_SECONDS} s while the main container does not answer yet (it
     * may start after this command, and its port opens a moment before it accepts containers); the
     * last failure is reported in one line. The port is not probed with a bare connection: JADE
     * would log that as an error.
     */
    private MaslContainer join(CommandLine line, DescriptorLoader descriptors, ContainerTranslator translator)
            throws InterruptedException {
        long deadline = System.nanoTime() + Duration.ofSeconds(JOIN_SECONDS).toNanos();
        while (true) {
            try {
                return MaslContainer.start(JadeOptions.join(line.mainHost, line.mainPort), line.containerName,
                        descriptors::loadByClassName, descriptors.implementationClasses(),
                        event -> out.println("masl-event " + event.getContent()), MissionSecret.Source.file(
                                line.secretFile != null ? Path.of(line.secretFile)
                                        : SecretFile.defaultFor(Path.of(""), line.mainPort)),
                        refusal -> err.println("masl: container " + line.containerName + ": " + refusal), translator);
            } catch (JadeException notYet) {
                if (System.nanoTime() - deadline > 0) {
                    throw notYet;
                }
            }
            Thread.sleep(200);
        }
    }
}
