package masl.bench.jade;

import jade.wrapper.AgentController;
import jade.wrapper.StaleProxyException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.atomic.AtomicLong;
import masl.jade.JadeLauncher;
import masl.jade.platform.AgentDeletion;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorLoader;

/**
 * The bridge's overhead: the ping-pong of {@link AclPingPong}, but each pong is
 * a MASL agent running inside JADE through the bridge ({@link JadeLauncher}), whose primitive
 * {@code nop} the pinger invokes; the request is served as MASL §5 serves external invocations (the
 * agent is blocked, so on its behalf, on its program's thread). Printed side by side with the raw
 * JADE figure measured in the same platform, and their ratio of round-trip times.
 *
 * <pre>
 * java -cp … masl.bench.jade.BridgePingPong [runs] [warm-up s] [window s]     (defaults: 5 1 3)
 * </pre>
 */
public final class BridgePingPong {

    private static final Duration MISSION_TIMEOUT = Duration.ofMinutes(10);
    private static final AgentType BENCH_AGENT = new DescriptorLoader(AgentPath.parse(""), null)
            .loadByClassName(BenchAgent.class.getName());
    private static int measurements;

    private BridgePingPong() {
    }

    public static void main(String[] args) throws Exception {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 5;
        Duration warmUp = Duration.ofMillis((long) (1000 * (args.length > 1 ? Double.parseDouble(args[1]) : 1)));
        Duration window = Duration.ofMillis((long) (1000 * (args.length > 2 ? Double.parseDouble(args[2]) : 3)));
        System.out.printf(Locale.ROOT, "FIPA REQUEST/INFORM round trips, one container, JDK %s, %d cores: "
                + "raw JADE pong vs MASL agent through the bridge (median of %d runs)%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(), runs);
        try (JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer())) {
            for (int pairs : new int[] {1, 10}) {
                double[] raw = new double[runs];
                double[] bridge = new double[runs];
                for (int run = 0; run < runs; run++) {
                    raw[run] = AclPingPong.measure(platform, pairs, warmUp, window).roundTripsPerSecond();
                    bridge[run] = measure(platform, pairs, warmUp, window).roundTripsPerSecond();
                }
                Arrays.sort(raw);
                Arrays.sort(bridge);
                double rawMedian = raw[runs / 2];
                double bridgeMedian = bridge[runs / 2];
                System.out.printf(Locale.ROOT, "pairs=%-3d raw %,10.0f/s (%6.1f us)  bridge %,10.0f/s (%6.1f us)"
                        + "  bridge/raw round-trip time %.2f%n", pairs, rawMedian, pairs * 1e6 / rawMedian,
                        bridgeMedian, pairs * 1e6 / bridgeMedian, rawMedian / bridgeMedian);
            }
        }
    }

    /**
     * Runs a mission of {@code pairs} MASL agents in {@code platform}'s container and as many plain
     * JADE pingers invoking them, as {@link AclPingPong#measure} does for raw JADE agents.
     *
     * @throws InterruptedException if the calling thread is interrupted meanwhile
     */
    public static AclPingPong.Result measure(JadePlatform platform, int pairs, Duration warmUp, Duration window)
            throws InterruptedException {
        int measurement = ++measurements;
        List<BenchAgent> servers = new ArrayList<>();
        CountDownLatch ready = new CountDownLatch(1);
        CompletableFuture<MissionOutcome> mission = CompletableFuture.supplyAsync(() -> {
            try {
                return JadeLauncher.of(program(measurement, pairs))
                        .types(spec -> BENCH_AGENT)
                        .implementations(spec -> {
                            BenchAgent server = new BenchAgent();
                            synchronized (servers) {
                                servers.add(server);
                            }
                            return server;
                        })
                        .whenReady(started -> ready.countDown())
                        .run(platform, MISSION_TIMEOUT);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted", e);
            }
        });
        List<AgentController> pingers = new ArrayList<>();
        try {
            Pinger.await(ready, "the MASL agents did not start");
            CountDownLatch started = new CountDownLatch(pairs);
            CountDownLatch go = new CountDownLatch(1);
            CountDownLatch finished = new CountDownLatch(pairs);
            AtomicLong roundTrips = new AtomicLong();
            Pinger.Run run = new Pinger.Run(started, go, finished, roundTrips, warmUp, window);
            for (int i = 0; i < pairs; i++) {
                pingers.add(platform.container().acceptNewAgent("bridge-ping-" + measurement + "-" + i,
                        new Pinger(serverName(measurement, i), run)));
            }
            for (AgentController pinger : pingers) {
                pinger.start();
            }
            Pinger.await(started, "the pingers did not start");
            go.countDown();
            Pinger.await(finished, "the pingers did not finish");
            return new AclPingPong.Result(pairs, roundTrips.get(), window);
        } catch (StaleProxyException e) {
            throw new IllegalStateException("the JADE container ended during the benchmark", e);
        } finally {
            AgentDeletion.oneByOne(pingers, Pinger.AGENTS_GONE_WITHIN);
            synchronized (servers) {
                servers.forEach(BenchAgent::release);
            }
            awaitEnd(mission);
        }
    }

    private static void awaitEnd(CompletableFuture<MissionOutcome> mission) throws InterruptedException {
        try {
            mission.get().requireCompleted();
        } catch (ExecutionException e) {
            throw new IllegalStateException("the MASL mission failed", e.getCause());
        }
    }

    private static String serverName(int measurement, int i) {
        return "bridge-pong-" + measurement + "-" + i;
    }

    /** {@code pairs} agents of type BenchAgent, each awaiting its release. */
    private static MissionProgram program(int measurement, int pairs) {
        List<MissionProgram.AgentSpec> agents = new ArrayList<>();
        for (int i = 0; i < pairs; i++) {
            agents.add(new MissionProgram.AgentSpec(serverName(measurement, i), BenchAgent.class.getName()));
        }
        return new MissionProgram() {
            @Override
            public List<AgentSpec> agents() {
                return agents;
            }

            @Override
            public Mission.Builder configure(Mission.Builder builder, ImplementationFactory implementations) {
                for (AgentSpec agent : agents) {
                    try {
                        BenchAgent server = (BenchAgent) implementations.create(agent);
                        builder.agent(agent.name(), server, BenchAgent.Program::new);
                    } catch (ReflectiveOperationException e) {
                        throw new IllegalStateException("cannot create " + agent.name(), e);
                    }
                }
                return builder;
            }
        };
    }
}
