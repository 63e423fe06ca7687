package masl.bench.jade;

import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.lang.acl.ACLMessage;
import jade.wrapper.AgentController;
import jade.wrapper.StaleProxyException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicLong;
import masl.jade.platform.AgentDeletion;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;

/**
 * The invocation benchmark's baseline: raw JADE {@code REQUEST}/{@code INFORM} round trips per second between
 * pairs of agents in one container, no MASL involved. Each pinger sends a request with the
 * bridge's JSON content and a fresh {@code reply-with}, waits for its pong's {@code INFORM}, and
 * sends the next; round trips are counted over a measuring window that follows a warm-up, all pairs
 * at once. A benchmark harness, not a test: {@code main} prints one line per run and the median.
 *
 * <pre>
 * java -cp … masl.bench.jade.AclPingPong [runs] [warm-up s] [window s]     (defaults: 5 1 3)
 * </pre>
 */
public final class AclPingPong {

    /** The figures of one measurement. */
    public record Result(int pairs, long roundTrips, Duration window) {

        public double roundTripsPerSecond() {
            return roundTrips / (window.toNanos() / 1e9);
        }

        /** Mean time of one round trip seen by one pair. */
        public double microsPerRoundTrip() {
            return pairs * 1e6 / roundTripsPerSecond();
        }
    }

    private static int measurements;

    private AclPingPong() {
    }

    public static void main(String[] args) throws Exception {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 5;
        Duration warmUp = Duration.ofMillis((long) (1000 * (args.length > 1 ? Double.parseDouble(args[1]) : 1)));
        Duration window = Duration.ofMillis((long) (1000 * (args.length > 2 ? Double.parseDouble(args[2]) : 3)));
        System.out.printf(Locale.ROOT, "JADE ACL REQUEST/INFORM ping-pong, one container, JDK %s, %d cores%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors());
        try (JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer())) {
            for (int pairs : new int[] {1, 10}) {
                double[] rates = new double[runs];
                for (int run = 0; run < runs; run++) {
                    Result result = measure(platform, pairs, warmUp, window);
                    rates[run] = result.roundTripsPerSecond();
                    System.out.printf(Locale.ROOT,
                            "pairs=%-3d run=%d  %,10.0f round trips/s  %7.1f us per round trip%n", pairs, run + 1,
                            result.roundTripsPerSecond(), result.microsPerRoundTrip());
                }
                Arrays.sort(rates);
                double median = rates[runs / 2];
                System.out.printf(Locale.ROOT, "pairs=%-3d median %,10.0f round trips/s  %7.1f us per round trip%n",
                        pairs, median, pairs * 1e6 / median);
            }
        }
    }

    /**
     * Runs {@code pairs} ping-pong pairs in {@code platform}'s container: all agents are created and
     * started first, then every pinger plays for {@code warmUp} plus {@code window}, and the round
     * trips completed within the window are counted. The agents are deleted afterwards.
     *
     * @throws InterruptedException if the calling thread is interrupted meanwhile
     */
    public static Result measure(JadePlatform platform, int pairs, Duration warmUp, Duration window)
            throws InterruptedException {
        int measurement = ++measurements;
        CountDownLatch started = new CountDownLatch(2 * pairs);
        CountDownLatch go = new CountDownLatch(1);
        CountDownLatch finished = new CountDownLatch(pairs);
        AtomicLong roundTrips = new AtomicLong();
        Pinger.Run run = new Pinger.Run(started, go, finished, roundTrips, warmUp, window);
        List<AgentController> agents = new ArrayList<>();
        try {
            for (int i = 0; i < pairs; i++) {
                String pong = "pong-" + measurement + "-" + i;
                agents.add(platform.container().acceptNewAgent(pong, new Pong(started)));
                agents.add(platform.container().acceptNewAgent("ping-" + measurement + "-" + i,
                        new Pinger(pong, run)));
            }
            for (AgentController agent : agents) {
                agent.start();
            }
            // Exchanges start once every agent exists (platform-notes.md: earlier ones can stall).
            Pinger.await(started, "the ping-pong agents did not start");
            go.countDown();
            Pinger.await(finished, "the pingers did not finish");
            return new Result(pairs, roundTrips.get(), window);
        } catch (StaleProxyException e) {
            throw new IllegalStateException("the JADE container ended during the benchmark", e);
        } finally {
            AgentDeletion.oneByOne(agents, Pinger.AGENTS_GONE_WITHIN);
        }
    }

    /** Answers every request with an {@code INFORM}. */
    private static final class Pong extends Agent {
        private static final long serialVersionUID = 1L;
        private final transient CountDownLatch started;

        Pong(CountDownLatch started) {
            this.started = started;
        }

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                private static final long serialVersionUID = 1L;

                @Override
                public void action() {
                    ACLMessage request = myAgent.receive();
                    if (request == null) {
                        block();
                        return;
                    }
                    ACLMessage inform = request.createReply();
                    inform.setPerformative(ACLMessage.INFORM);
                    inform.setContent("{\"result\":null}");
                    myAgent.send(inform);
                }
            });
            started.countDown();
        }
    }
}
