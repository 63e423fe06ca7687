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
import java.util.concurrent.atomic.AtomicInteger;
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
 * Missions whose agents run in two other JVMs, as a user deploys them: {@code masl container} of the
 * installed command ({@code masl-cli/build/install}, which {@code gradle bench} installs first), two
 * fresh ones per mission (a container serves one mission and ends with it), joined to a main container
 * in this JVM, where the mission runs through {@link JadeLauncher} as {@code masl run --platform jade}
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
     * messages per step and container, each way. The containers' JVMs are fresh for each mission: the
     * first few hundred steps run while their JIT compiles JADE's, Jackson's and the program's code,
     * and the later half shows the rate of a mission that runs for long.
     */
    record Figures(double stepsPerSecond, double laterStepsPerSecond, double toContainerPerStep,
            double fromContainerPerStep, JvmCpu.PerStep cpu) {
    }

    /**
     * Each mission's two containers are named after it: a container that served the last mission may
     * still be known to the platform, its departure not yet seen, and a new one of the same name would
     * not be let in.
     */
    private final AtomicInteger missionNumbers = new AtomicInteger();
    private static final Duration MISSION_TIMEOUT = Duration.ofMinutes(10);

    private final Path masl;
    private final Path work;

    private DeployedMissions(Path masl, Path work) {
        this.masl = masl;
        this.work = work;
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
        int mission = missionNumbers.incrementAndGet();
        List<String> containerNames = List.of("c2-" + mission, "c3-" + mission);
        Map<String, String> spread = new LinkedHashMap<>();
        for (int i = 0; i < names.size(); i++) {
            spread.put(names.get(i), containerNames.get(i % containerNames.size()));
        }
        MissionSecret secret = MissionSecret.generate();
        Path secretFile = work.resolve("secret-" + System.nanoTime());
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
        List<Process> containers = new ArrayList<>();
        JvmCpu.PerStep perStep;
        try (SecretFile shared = secret.writeTo(secretFile); JvmCpu cpu = new JvmCpu(trips)) {
            for (String container : containerNames) {
                containers.add(container(platform, container, secretFile));
                cpu.container(containers.get(containers.size() - 1));
            }
            MissionOutcome outcome = launcher.run(platform, MISSION_TIMEOUT);
            perStep = cpu.perStep();
            outcome.requireCompleted();
        } finally {
            for (Process container : containers) {
                if (!container.waitFor(60, TimeUnit.SECONDS)) {
                    container.destroyForcibly();
                }
            }
        }
        double perContainerStep = (double) trips.count() * containerNames.size();
        return new Figures(trips.stepsPerSecond(), trips.laterStepsPerSecond(), sum(traffic.sent()) / perContainerStep,
                sum(traffic.received()) / perContainerStep, perStep);
    }

    /** Deletes the containers' logs and the folder they were written to. */
    void close() throws IOException {
        try (Stream<Path> files = Files.walk(work)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(file);
            }
        }
    }

    private static long sum(Map<String, Long> counts) {
        return counts.values().stream().mapToLong(Long::longValue).sum();
    }

    private Process container(JadePlatform platform, String name, Path secretFile) throws IOException {
        return new ProcessBuilder(masl.toString(), "container", "--main-host", platform.host(), "--main-port",
                String.valueOf(platform.port()), "--name", name, "--timeout", "600", "--secret-file", secretFile.toString())
                .redirectErrorStream(true)
                .redirectOutput(work.resolve(name + ".log").toFile())
                .start();
    }
}
