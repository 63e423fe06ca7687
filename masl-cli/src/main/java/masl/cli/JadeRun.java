package masl.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;
import java.util.stream.Collectors;
import masl.jade.JadeLauncher;
import masl.jade.external.ExternalAgents;
import masl.jade.placement.DeployedSource;
import masl.jade.placement.Deployment;
import masl.jade.placement.Placement;
import masl.jade.platform.JadeException;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.platform.Readiness;
import masl.jade.trust.MissionSecret;
import masl.jade.trust.SecretFile;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.DescriptorLoader;
import masl.translator.MissionLoader;
import masl.translator.TranslationKey;
import masl.translator.source.SourceFile;

/**
 * {@code masl run --platform jade}: runs a translated mission inside JADE through {@link JadeLauncher},
 * in a new main container on loopback, or in a container joining the platform at
 * {@code --main-host}/{@code --main-port}; with {@code --place}, the bodies of the agents named run in
 * the containers named ({@code masl container}), their programs here; with {@code --deploy}, their
 * programs too, translated there from the source sent (the mission itself stays here). The journal, timeout, trace,
 * signals and outcome are those of an in-process run; a platform that cannot start or be joined, or a
 * container that does not join, ends the run as a failed mission. Once the platform accepts containers,
 * one line on standard error says where ({@link Readiness#platform}).
 */
final class JadeRun {

    private final MissionLoader loaded;
    private final DescriptorLoader descriptors;
    private final JadeOptions options;
    private final Map<String, String> placement;
    private final Map<String, String> deployment;
    private final DeployedSource deployedSource;
    private final JournalOutput journal;
    /** {@code --secret-file}, or null: {@link SecretFile#defaultFor} the platform. */
    private final Path secretFile;
    private final Duration callTimeout;
    private final PrintStream err;

    /**
     * @throws UsageException if the command line asks for something JADE runs cannot do: a scheduler
     *                        of its own ({@code --threads}, {@code --seed}), or half a main address
     */
    JadeRun(CommandLine line, SourceFile source, AgentPath agentPath, MissionLoader loaded, JournalOutput journal,
            PrintStream err) throws UsageException {
        if (line.threads || line.seed != null) {
            throw new UsageException("--platform jade runs each agent in a JADE behaviour of its own:"
                    + " --threads and --seed are for --platform inproc");
        }
        if ((line.mainHost == null) != (line.mainPort == null)) {
            throw new UsageException("--main-host and --main-port name the main container to join: give both");
        }
        if (line.port != null && line.mainHost != null) {
            throw new UsageException("--port is the port of the main container masl run starts: --main-host and"
                    + " --main-port join one instead");
        }
        this.loaded = loaded;
        this.descriptors = new DescriptorLoader(agentPath.withFirst(source.folder()));
        String localHost = LocalHost.checked(line.localHost);
        if (line.mainHost != null) {
            LocalHost.reachableFrom(line.mainHost, localHost);
        }
        JadeOptions platform = line.mainHost != null ? JadeOptions.join(line.mainHost, line.mainPort)
                : line.port != null ? JadeOptions.mainContainer().withPort(line.port) : JadeOptions.mainContainer();
        this.options = localHost != null ? platform.withLocalHost(localHost) : platform;
        this.placement = line.place == null ? Map.of() : placement(line.place, loaded);
        this.deployment = line.deploy == null ? Map.of() : deployment(line.deploy, loaded, placement.keySet(), descriptors);
        this.deployedSource = deployment.isEmpty() ? null : deployedSource(source);
        this.journal = journal;
        if (line.secretFile != null && placement.isEmpty() && deployment.isEmpty()) {
            throw new UsageException("--secret-file is where the containers of --place and --deploy find the mission's"
                    + " secret: give it with --place or --deploy");
        }
        this.secretFile = line.secretFile == null ? null : Path.of(line.secretFile);
        this.callTimeout = line.callTimeoutMillis == null ? null : Duration.ofMillis(line.callTimeoutMillis);
        this.err = err;
    }

    /** {@code --place}: pairs or a file, naming agents the program declares. */
    private static Map<String, String> placement(String option, MissionLoader loaded) throws UsageException {
        Map<String, String> placement;
        try {
            placement = Placement.parse(option);
        } catch (IllegalArgumentException bad) {
            throw new UsageException(bad.getMessage());
        }
        List<String> declared = loaded.program().agents().stream().map(MissionProgram.AgentSpec::name).toList();
        for (String agent : placement.keySet()) {
            if (!declared.contains(agent)) {
                throw new UsageException("--place names " + agent + ", which the program does not declare (it"
                        + " declares " + String.join(", ", declared) + ")");
            }
        }
        return placement;
    }

    /** {@code --deploy}: agents the program declares, neither placed nor external FIPA agents, to containers. */
    private static Map<String, String> deployment(String option, MissionLoader loaded, Set<String> placed,
            DescriptorLoader descriptors) throws UsageException {
        List<MissionProgram.AgentSpec> agents = loaded.program().agents();
        Set<String> external = agents.stream()
                .filter(spec -> ExternalAgents.isExternal(descriptors.loadByClassName(spec.typeClassName())))
                .map(MissionProgram.AgentSpec::name).collect(Collectors.toSet());
        try {
            return Deployment.parse(option, agents.stream().map(MissionProgram.AgentSpec::name).toList(), placed,
                    external);
        } catch (IllegalArgumentException bad) {
            throw new UsageException(bad.getMessage());
        }
    }

    /**
     * What the containers of {@code --deploy} translate themselves: the program, the descriptors beside it
     * (the {@code .xml} files of its folder), and the key of this masl's translation of them.
     */
    private static DeployedSource deployedSource(SourceFile source) throws UsageException {
        Map<String, String> descriptors = new TreeMap<>();
        Path folder = source.folder() == null ? Path.of("") : source.folder();
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder, "*.xml")) {
            for (Path file : files) {
                if (Files.isRegularFile(file)) {
                    descriptors.put(file.getFileName().toString(), Files.readString(file));
                }
            }
        } catch (IOException | UncheckedIOException unreadable) {
            throw new UsageException("cannot read the descriptors beside " + source.name() + " to send them to the"
                    + " containers of --deploy: " + unreadable.getMessage());
        }
        String name = Path.of(source.name()).getFileName().toString();
        return new DeployedSource(name, source.text(), descriptors, TranslationKey.of(name, source.text(), descriptors));
    }

    /**
     * Runs the mission; a signal stops it once its agents exist ({@link StopOnSignal}), and so does a
     * journal or a trace that cannot be written.
     */
    MissionOutcome run(TraceOutput trace, Duration timeout, StopOnSignal signals) {
        JadeLauncher launcher = JadeLauncher.of(loaded.program())
                .types(spec -> descriptors.loadByClassName(spec.typeClassName()))
                .implementations(loaded::newImplementation)
                .place(placement)
                .deploy(deployment, deployedSource)
                .journal(journal)
                .problems(problem -> err.println("masl: " + problem))
                .trace(trace.trace())
                .whenReady(mission -> {
                    journal.whenFailed(() -> mission.stop(RunCommand.JOURNAL_LOST));
                    trace.whenFailed(() -> mission.stop(TraceOutput.TRACE_LOST));
                    if (!signals.stops(mission::stop)) {
                        mission.stop(StopOnSignal.REASON);
                    }
                });
        if (callTimeout != null) {
            launcher.callTimeout(callTimeout);
        }
        // Standard output is the journal's alone: JADE prints some notices of its own there, which go to standard error.
        PrintStream standardOutput = System.out;
        System.setOut(new JadeNotices(err));
        try {
            return runOn(launcher, timeout);
        } finally {
            System.setOut(standardOutput);
        }
    }

    private MissionOutcome runOn(JadeLauncher launcher, Duration timeout) {
        try (JadePlatform platform = JadePlatform.start(options)) {
            Optional<SecretFile> shared = placement.isEmpty() && deployment.isEmpty() ? Optional.empty()
                    : Optional.of(shareSecret(platform, launcher));
            try {
                err.println(Readiness.platform(platform));
                err.flush();
                return launcher.run(platform, timeout);
            } finally {
                shared.ifPresent(SecretFile::close);
            }
        } catch (UnsharedSecret unwritable) {
            return failed(new PlatformFailure(unwritable.getMessage()), MissionOutcome.Status.FAILED);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            return failed(interrupted, MissionOutcome.Status.STOPPED);
        } catch (JadeException platform) {
            return failed(new PlatformFailure(platform.getMessage()), MissionOutcome.Status.FAILED);
        } catch (IllegalStateException cannotRun) {
            return failed(cannotRun, MissionOutcome.Status.FAILED);
        }
    }

    /**
     * A fresh secret for this mission, written to a new file (owner-only), {@code --secret-file} or
     * the platform's default, for the containers of {@code --place} to read when its coordinator
     * first writes to them; written before the readiness line, so a container started on that line
     * finds it. A file already there is refused and left as it was.
     */
    private SecretFile shareSecret(JadePlatform platform, JadeLauncher launcher) throws UnsharedSecret {
        Path file = secretFile != null ? secretFile : SecretFile.defaultFor(Path.of(""), platform.mainPort());
        MissionSecret secret = MissionSecret.generate();
        try {
            SecretFile shared = secret.writeTo(file);
            launcher.secret(secret);
            return shared;
        } catch (IOException unwritable) {
            throw new UnsharedSecret("cannot write the mission's secret for its containers to " + file + ": "
                    + unwritable.getMessage());
        }
    }

    /** The mission's secret could not be handed to its containers: the mission does not start. */
    private static final class UnsharedSecret extends Exception {
        UnsharedSecret(String message) {
            super(message);
        }
    }

    private static MissionOutcome failed(Exception why, MissionOutcome.Status status) {
        return new MissionOutcome(status, "", Optional.of(why), "");
    }
}
