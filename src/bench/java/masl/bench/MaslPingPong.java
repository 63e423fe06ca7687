package masl.bench;

import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.Mission;
import masl.runtime.scheduling.PoolScheduler;
import masl.translator.MissionLoader;

/**
 * MASL's side of the invocation benchmark: pairs of agents in one mission on the
 * default pool, each pinger invoking its pong's primitive {@code nop} synchronously a fixed number
 * of times, as the JADE pingers of {@code AclPingPong} do; the rate is all the round trips over the
 * mission's run. The pongs skip {@code main} and finish, so each invocation is served on the pong's
 * behalf (MASL §5), as a JADE pong blocked on its message queue serves a request. Translated and
 * compiled as {@code masl run} does, before the clock starts:
 *
 * <pre>
 * Default p0, q0, p1, q1 = newAgent(Default);
 * asynchronous entry main (.getProxyID() % 2 == 0) {
 *   local Default partner = q0;
 *   local int i = 0;
 *   if (.getProxyID() == 2) partner = q1;
 *   while (i &lt; ROUND_TRIPS) { partner.nop(); i++; }
 * }
 * </pre>
 */
final class MaslPingPong {

    private MaslPingPong() {
    }

    /** The call runs {@code pairs} pairs of {@code roundTrips} round trips each, all at once, and returns round trips per second. */
    static Callable<Double> prepare(int pairs, int roundTrips) {
        MissionLoader program = MaslLockStep.compile(source(pairs, roundTrips));
        return () -> {
            Mission mission = program.newMission().scheduler(new PoolScheduler()).journal(new StringBuilder()).build();
            long start = System.nanoTime();
            mission.run(Duration.ofMinutes(10)).requireCompleted();
            return (double) pairs * roundTrips / ((System.nanoTime() - start) / 1e9);
        };
    }

    static String source(int pairs, int roundTrips) {
        String names = IntStream.range(0, pairs).mapToObj(i -> "p" + i + ", q" + i).collect(Collectors.joining(", "));
        String partners = IntStream.range(1, pairs)
                .mapToObj(i -> "  if (.getProxyID() == " + 2 * i + ") partner = q" + i + ";\n")
                .collect(Collectors.joining());
        return """
                import Default.xml as Default;
                Default %s = newAgent(Default);
                asynchronous entry main (.getProxyID() %% 2 == 0) {
                  local Default partner = q0;
                  local int i = 0;
                %s  while (i < %d) {
                    partner.nop();
                    i++;
                  }
                }
                """.formatted(names, partners, roundTrips);
    }
}
