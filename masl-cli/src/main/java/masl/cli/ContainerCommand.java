package masl.cli;

import java.io.IOException;
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
 * <p>With {@code --serve} it serves one mission after another, as a robot's runtime does: once a
 * mission ended (or was lost), it waits until the secret file holds another mission's secret, which a
 * new {@code masl run} writes once its platform is up, joins that platform, and so on; a mission that
 * fails here is said in its line and the next is served. {@code --timeout} then bounds each mission,
 * the wait for it included, and the main container is waited for that long too; it exits 2 once a
 * mission did not end within it, and ends otherwise when stopped (SIGTERM, Ctrl-C).
 */
final class ContainerCommand {

    private static final long JOIN_SECONDS = 30;
    private static final Duration NO_TIMEOUT = Duration.ofDays(3650);
    /** How often a serving container looks for the next mission's secret. */
    private static final long SECRET_POLL_MILLIS = 100;

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
        String localHost = LocalHost.checked(line.localHost);
        LocalHost.reachableFrom(line.mainHost, localHost);
        DescriptorLoader descriptors = new DescriptorLoader(AgentPath.parse(line.agentPath));
        Duration timeout = line.timeoutSeconds == null ? NO_TIMEOUT : Duration.ofSeconds(line.timeoutSeconds);
        MissionSecret.Source secret = MissionSecret.Source.file(line.secretFile != null ? Path.of(line.secretFile)
                : SecretFile.defaultFor(Path.of(""), line.mainPort));
        MissionSecret previous = null;
        while (true) {
            Served served = serve(line, descriptors, secret, timeout, previous);
            if (!line.serve || served.last()) {
                return served.status();
            }
            previous = served.secret();
        }
    }

    /**
     * What one mission left: the status of a container that served it alone, the secret of that
     * mission (null if none is known), and whether no further mission can be served.
     */
    private record Served(int status, MissionSecret secret, boolean last) {
    }

    /**
     * Serves one mission, at most {@code timeout} from now: joins the platform (serving: once the
     * secret file holds a secret other than {@code previous}, the last mission's), hosts what the
     * coordinator places here, and waits for the mission's end.
     */
    private Served serve(CommandLine line, DescriptorLoader descriptors, MissionSecret.Source secret, Duration timeout,
            MissionSecret previous) {
        long deadline = System.nanoTime() + timeout.toNanos();
        try (ContainerTranslator translator = new ContainerTranslator(AgentPath.parse(line.agentPath))) {
            MissionSecret joinedUnder = line.serve ? awaitNewSecret(secret, previous, deadline) : null;
            if (line.serve && joinedUnder == null) {
                return new Served(noMission(line, timeout), null, true);
            }
            MaslContainer container = join(line, descriptors, secret, translator,
                    line.serve ? deadline : System.nanoTime() + Duration.ofSeconds(JOIN_SECONDS).toNanos());
            Served served;
            try {
                served = awaitEnd(line, container, timeout, deadline);
            } finally {
                out.flush();
                if (!leave(line, container)) {
                    served = new Served(Masl.MISSION_FAILED, container.missionSecret().orElse(null), !line.serve);
                }
            }
            return served.secret() != null ? served : new Served(served.status(), joinedUnder, served.last());
        } catch (JadeException cannotJoin) {
            err.println("masl: container " + line.containerName + ": " + cannotJoin.getMessage());
            return new Served(Masl.MISSION_FAILED, null, true);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            return new Served(Masl.MISSION_FAILED, null, true);
        } finally {
            out.flush();
            err.flush();
        }
    }

    /** Says that the container's bodies are placed, waits for the mission's end, and says how it ended. */
    private Served awaitEnd(CommandLine line, MaslContainer container, Duration timeout, long deadline)
            throws InterruptedException {
        if (container.awaitBodies(timeout)) {
            err.println(container.readiness());
            err.flush();
        }
        boolean ended = container.awaitMissionEnd(Duration.ofNanos(Math.max(0, deadline - System.nanoTime())));
        MissionSecret served = container.missionSecret().orElse(null);
        if (!ended) {
            return new Served(noMission(line, timeout), served, true);
        }
        if (container.unhosted().isPresent()) {
            err.println("masl: " + container.unhosted().get());
            return new Served(Masl.MISSION_FAILED, served, false);
        }
        if (container.lostPlatform().isPresent()) {
            err.println("masl: container " + line.containerName + ": " + container.lostPlatform().get()
                    + (container.hostedAgents().isEmpty() ? "" : "; its agents were stopped"));
            return new Served(Masl.MISSION_FAILED, served, false);
        }
        out.println("masl-ended hosted " + String.join(",", container.hostedAgents()));
        return new Served(Masl.OK, served, false);
    }

    /**
     * Closes the container (serving: without waiting for JADE's threads, which the next container of
     * this JVM reuses); false, said in one line, if JADE did not end as it should.
     */
    private boolean leave(CommandLine line, MaslContainer container) {
        try {
            if (line.serve) {
                container.leave();
            } else {
                container.close();
            }
            return true;
        } catch (JadeException unended) {
            err.println("masl: container " + line.containerName + ": " + unended.getMessage());
            return false;
        }
    }

    private int noMission(CommandLine line, Duration timeout) {
        err.println("masl: container " + line.containerName + ": no mission ended within " + timeout.toSeconds() + " s");
        return Masl.MISSION_FAILED;
    }

    /** The secret in the file now, or null if it holds none. */
    private static MissionSecret readOrNull(MissionSecret.Source secret) {
        try {
            return secret.get();
        } catch (IOException none) {
            return null;
        }
    }

    /**
     * Waits until the secret file holds a secret other than {@code previous} (any, if null): that of a
     * mission whose {@code masl run} wrote it once its platform listened, so that the platform at the
     * container's address is that mission's and not the last one's shutting down. The secret, which
     * stands for that mission after it even if its coordinator never writes here; null if
     * {@code deadline} passed first.
     */
    private static MissionSecret awaitNewSecret(MissionSecret.Source secret, MissionSecret previous, long deadline)
            throws InterruptedException {
        while (System.nanoTime() - deadline < 0) {
            MissionSecret now = readOrNull(secret);
            if (now != null && (previous == null || !now.sameAs(previous))) {
                return now;
            }
            Thread.sleep(SECRET_POLL_MILLIS);
        }
        return null;
    }

    /** The platform to join, and this container's own address there: loopback unless {@code --local-host}. */
    private static JadeOptions platform(CommandLine line) {
        JadeOptions join = JadeOptions.join(line.mainHost, line.mainPort);
        return line.localHost == null ? join : join.withLocalHost(line.localHost);
    }

    /**
     * Joins, retrying for {@value #JOIN_SECONDS} s while the main container does not answer yet (it
     * may start after this command, and its port opens a moment before it accepts containers); the
     * last failure is reported in one line. Serving, the platform listens already (its mission wrote
     * its secret), so a failure is news: each new one is said at once, with the retrying. The port is
     * not probed with a bare connection: JADE would log that as an error.
     */
    private MaslContainer join(CommandLine line, DescriptorLoader descriptors, MissionSecret.Source secret,
            ContainerTranslator translator, long deadline) throws InterruptedException {
        String said = null;
        while (true) {
            try {
                return MaslContainer.start(platform(line), line.containerName,
                        descriptors::loadByClassName, descriptors.implementationClasses(),
                        event -> out.println("masl-event " + event.getContent()), secret,
                        refusal -> err.println("masl: container " + line.containerName + ": " + refusal), translator);
            } catch (JadeException notYet) {
                if (System.nanoTime() - deadline > 0) {
                    throw notYet;
                }
                if (line.serve && !notYet.getMessage().equals(said)) {
                    said = notYet.getMessage();
                    err.println("masl: container " + line.containerName + ": " + said + "; trying again until the mission's timeout");
                    err.flush();
                }
            }
            Thread.sleep(200);
        }
    }
}
