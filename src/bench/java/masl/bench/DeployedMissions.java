package masl.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import masl.jade.JadeLauncher;
import masl.jade.placement.ContainerTraffic;
import masl.jade.placement.DeployedSource;
import masl.jade.platform.JadePlatform;
import masl.jade.trust.MissionSecret;
import masl.jade.trust.SecretFile;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.trace.TraceEvent;
import masl.translator.MissionLoader;
import masl.translator.TranslationKey;

/**
 * Missions whose agents run in two other JVMs, as a user deploys them: {@code masl container --serve}
 * of the installed command ({@code masl-cli/build/install}, which {@code gradle bench} installs first),
 * two started with the first mission and serving each next one, as a robot's container does, joined to
 * a main container in this JVM, where the mission runs through {@link JadeLauncher} as {@code masl run --platform jade}
 * runs it. Agents are spread over the two containers in turn ({@code --deploy '*=c2+c3'}, or
 * {@code --place} likewise). Steps are the barrier trips of the mission's trace, timed from the end
 * of the first (the containers' start left out), over the whole mission and over its later half
 * ({@link TripTimes}); messages are those
 * the coordinator sent to and took from the containers ({@link ContainerTraffic}): deployed agents'
 * coordination messages, or placed bodies' primitive calls and their answers.
 */
final class DeployedMissions {

    /** Where each agent's program and body run. */
    enum Where { IN_PROCESS, PLACED, DEPLOYED }

    /**
     * A run: steps per second over the whole mission and over its later half, and coordination
     * messages per step and container, each way. The containers' JVMs served the missions before
     * (a warm-up one at least), so that their JIT has compiled JADE's, Jackson's and the bridge's code;
     * each mission's program is translated and compiled anew, and the later half leaves its first
     * steps out.
     */
    record Figures(double stepsPerSecond, double laterStepsPerSecond, double toContainerPerStep,
            double fromContainerPerStep, JvmCpu.PerStep cpu) {
    }

    private static final Duration MISSION_TIMEOUT = Duration.ofMinutes(10);
    private static final List<String> CONTAINERS = List.of("c2", "c3");

    private final Path masl;
    private final Path work;
    /** Where each mission writes its secret, which the serving containers wait for anew. */
    private final Path secretFile;
    /** The serving containers, started with the first mission in containers. */
    private final List<Process> serving = new ArrayList<>();

    private DeployedMissions(Path masl, Path work) {
        this.masl = masl;
        this.work = work;
        this.secretFile = work.resolve("secret");
    }

    /** With the installed command of {@code gradle bench}. */
    static DeployedMissions installed() throws IOException {
        Path home = Path.of(System.getProperty("masl.bench.home", ".")).toAbsolutePath();
        Path masl = home.resolve("masl-cli/build/install/masl/bin/masl");
        if (!Files.isExecutable(masl)) {
            throw new IllegalStateException(masl + " is missing: gradle bench installs it (:masl-cli:installDist)");
        }
        return new DeployedMissions(masl, Files.createTempDirectory("masl-bench-deployed"));
    }

    /** N agents in one synchronous block, {@code steps} steps of one trivial instruction each. */
    static String lockStep(int agents, int steps) {
        return MaslLockStep.source(agents, steps);
    }

    /**
     * N agents in one synchronous block, each step one instruction calling ten of the agent's own
     * primitives ({@code getProxyID}, which Default's permeability lets an agent call on itself):
     * a sensor loop of ten readings.
     */
    static String tenOwnPrimitives(int agents, int steps) {
        String names = IntStream.range(0, agents).mapToObj(i -> "a" + i).collect(Collectors.joining(", "));
        return """
                import Default.xml as Default;
                Default %s = newAgent(Default);
                synchronous entry main (true) {
                  local int i = 0;
                  while (i < %d) {
                    i = i + 1 + .getProxyID() - .getProxyID() + .getProxyID() - .getProxyID() + .getProxyID()
                        - .getProxyID() + .getProxyID() - .getProxyID() + .getProxyID() - .getProxyID();
                  }
                }
                """.formatted(names, steps);
    }

    /** One run of {@code source} with its agents {@code where}; the platform's main container is this JVM's. */
    Callable<Figures> prepare(JadePlatform platform, String source, Where where) {
        MissionLoader program = MaslLockStep.compile(source);
        return () -> where == Where.IN_PROCESS ? inProcess(program) : inContainers(platform, program, source, where);
    }

    private static Figures inProcess(MissionLoader program) throws InterruptedException {
        TripTimes trips = new TripTimes();
        program.newMission().journal(new StringBuilder()).trace(event -> {
            if (event instanceof TraceEvent.BarrierTripped) {
                trips.tripped();
            }
        }).build().run(MISSION_TIMEOUT).requireCompleted();
        return new Figures(trips.stepsPerSecond(), trips.laterStepsPerSecond(), 0, 0, JvmCpu.PerStep.NOT_READ);
    }

    private Figures inContainers(JadePlatform platform, MissionLoader program, String source, Where where)
            throws Exception {
        List<String> names = program.program().agents().stream().map(agent -> agent.name()).toList();
        Map<String, String> spread = new LinkedHashMap<>();
        for (int i = 0; i < names.size(); i++) {
            spread.put(names.get(i), CONTAINERS.get(i % CONTAINERS.size()));
        }
        MissionSecret secret = MissionSecret.generate();
        TripTimes trips = new TripTimes();
        ContainerTraffic traffic = new ContainerTraffic();
        DescriptorLoader descriptors = new DescriptorLoader(AgentPath.parse(""), null);
        JadeLauncher launcher = JadeLauncher.of(program.program())
                .types(spec -> descriptors.loadByClassName(spec.typeClassName()))
                .implementations(program::newImplementation)
                .journal(new StringBuilder())
                .secret(secret)
                .traffic(traffic)
                .trace(event -> {
                    if (event instanceof TraceEvent.BarrierTripped) {
                        trips.tripped();
                    }
                });
        if (where == Where.DEPLOYED) {
            launcher.deploy(spread, new DeployedSource("bench.masl", source, Map.of(),
                    TranslationKey.of("bench.masl", source, Map.of())));
        } else {
            launcher.place(spread);
        }
        JvmCpu.PerStep perStep;
        try (SecretFile shared = secret.writeTo(secretFile); JvmCpu cpu = new JvmCpu(trips)) {
            if (serving.isEmpty()) {
                for (String container : CONTAINERS) {
                    serving.add(container(platform, container));
                }
            }
            serving.forEach(cpu::container);
            MissionOutcome outcome = launcher.run(platform, MISSION_TIMEOUT);
            perStep = cpu.perStep();
            outcome.requireCompleted();
        }
        double perContainerStep = (double) trips.count() * CONTAINERS.size();
        return new Figures(trips.stepsPerSecond(), trips.laterStepsPerSecond(), sum(traffic.sent()) / perContainerStep,
                sum(traffic.received()) / perContainerStep, perStep);
    }

    /** Stops the serving containers, and deletes their logs and the folder they were written to. */
    void close() throws IOException, InterruptedException {
        for (Process container : serving) {
            container.destroy();
            if (!container.waitFor(30, TimeUnit.SECONDS)) {
                container.destroyForcibly();
            }
        }
        try (Stream<Path> files = Files.walk(work)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(file);
            }
        }
    }

    private static long sum(Map<String, Long> counts) {
        return counts.values().stream().mapToLong(Long::longValue).sum();
    }

    private Process container(JadePlatform platform, String name) throws IOException {
        return new ProcessBuilder(masl.toString(), "container", "--serve", "--main-host", platform.host(), "--main-port",
                String.valueOf(platform.port()), "--name", name, "--timeout", "600", "--secret-file", secretFile.toString())
                .redirectErrorStream(true)
                .redirectOutput(work.resolve(name + ".log").toFile())
                .start();
    }
}
