package masl.bench;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.CyclicBehaviour;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.ACLMessage;
import jade.lang.acl.MessageTemplate;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;

/**
 * JADE's own round trip between two JVMs on this machine, the floor under a deployed mission's step
 * (two hops between the coordinator's JVM and a container's): an agent of a container joined from a
 * second JVM sends a {@code REQUEST} to an agent of the main container in this JVM, which answers
 * with an {@code INFORM} of the same content, one after the other; content of 100 bytes, 6 KB and
 * 60 KB (a deployed lock-step batch of 50 and 500 agents' messages). Prints the 10th percentile,
 * median and 90th percentile of the round trips after a warm-up. No MASL involved.
 *
 * <pre>
 * gradle jvmHops                                             (-PprobeArgs="round trips per size")
 * </pre>
 */
public final class JvmHops {

    private static final int[] SIZES = {100, 6_000, 60_000};

    private JvmHops() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && args[0].equals("--join")) {
            join(args[1], Integer.parseInt(args[2]), Integer.parseInt(args[3]));
            return;
        }
        int roundTrips = args.length > 0 ? Integer.parseInt(args[0]) : 2_000;
        System.out.printf(Locale.ROOT, "JADE REQUEST/INFORM round trips between two JVMs on loopback, JDK %s, %d cores, %s%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(),
                Bench.loadAverage());
        try (JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer())) {
            platform.container().acceptNewAgent("pong", new Pong()).start();
            Path java = Path.of(System.getProperty("java.home"), "bin", "java");
            Process joined = new ProcessBuilder(java.toString(), "-cp", System.getProperty("java.class.path"),
                    JvmHops.class.getName(), "--join", platform.host(), String.valueOf(platform.port()),
                    String.valueOf(roundTrips)).inheritIO().start();
            if (!joined.waitFor(10, TimeUnit.MINUTES)) {
                joined.destroyForcibly();
                throw new IllegalStateException("the joined JVM did not end");
            }
        }
    }

    private static void join(String host, int port, int roundTrips) throws Exception {
        CountDownLatch done = new CountDownLatch(1);
        try (JadePlatform platform = JadePlatform.start(JadeOptions.join(host, port))) {
            platform.container().acceptNewAgent("ping", new Ping(roundTrips, done)).start();
            if (!done.await(10, TimeUnit.MINUTES)) {
                throw new IllegalStateException("the pinger did not finish");
            }
        }
    }

    /** Answers every request with an {@code INFORM} of its content. */
    private static final class Pong extends Agent {
        private static final long serialVersionUID = 1L;

        @Override
        protected void setup() {
            addBehaviour(new CyclicBehaviour(this) {
                private static final long serialVersionUID = 1L;

                @Override
                public void action() {
                    ACLMessage request = receive();
                    if (request == null) {
                        block();
                        return;
                    }
                    ACLMessage reply = request.createReply();
                    reply.setPerformative(ACLMessage.INFORM);
                    reply.setContent(request.getContent());
                    send(reply);
                }
            });
        }
    }

    /** Plays the round trips of each size, from its own thread, with blocking receives. */
    private static final class Ping extends Agent {
        private static final long serialVersionUID = 1L;
        private final transient int roundTrips;
        private final transient CountDownLatch done;

        Ping(int roundTrips, CountDownLatch done) {
            this.roundTrips = roundTrips;
            this.done = done;
        }

        @Override
        protected void setup() {
            addBehaviour(new OneShotBehaviour(this) {
                private static final long serialVersionUID = 1L;

                @Override
                public void action() {
                    try {
                        for (int size : SIZES) {
                            play(size, roundTrips / 2); // warm-up
                            long[] times = play(size, roundTrips);
                            Arrays.sort(times);
                            System.out.printf(Locale.ROOT, "content %,7d bytes: %,d round trips, p10 %.0f us, median %.0f us, p90 %.0f us%n",
                                    size, roundTrips, times[times.length / 10] / 1e3, times[times.length / 2] / 1e3,
                                    times[times.length * 9 / 10] / 1e3);
                        }
                    } finally {
                        done.countDown();
                    }
                }
            });
        }

        private long[] play(int size, int count) {
            AID pong = new AID("pong", AID.ISLOCALNAME);
            String content = "x".repeat(size);
            long[] times = new long[count];
            for (int i = 0; i < count; i++) {
                ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
                request.addReceiver(pong);
                request.setContent(content);
                String replyWith = "r" + size + "-" + i;
                request.setReplyWith(replyWith);
                long start = System.nanoTime();
                send(request);
                ACLMessage answer = blockingReceive(MessageTemplate.MatchInReplyTo(replyWith), 30_000);
                if (answer == null) {
                    throw new IllegalStateException("no answer within 30 s");
                }
                times[i] = System.nanoTime() - start;
            }
            return times;
        }
    }
}
