package masl.bench;

import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.Mission;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.trace.TraceEvent;
import masl.translator.MissionLoader;

/**
 * The joining benchmark: the time for N agents to enter a synchronous block and
 * pass its entry barrier, from the start of the mission (its agents made runnable on a fresh pool)
 * to the release of the last of them, read from the trace. Translating, compiling and creating
 * the agents come before and are left out.
 */
final class MaslJoining {

    private MaslJoining() {
    }

    /** Prepares a mission of {@code agents} agents; the call runs it and returns the joining time in seconds. */
    static Callable<Double> prepare(int agents) {
        MissionLoader program = MaslLockStep.compile(source(agents));
        AtomicInteger released = new AtomicInteger();
        long[] lastReleased = new long[1];
        Mission mission = program.newMission()
                .scheduler(new PoolScheduler())
                .journal(new StringBuilder())
                .trace(event -> {
                    // Recorded under the coordinator's lock: one writer at a time.
                    if (event instanceof TraceEvent.Released && released.incrementAndGet() == agents) {
                        lastReleased[0] = System.nanoTime();
                    }
                })
                .build();
        return () -> {
            long start = System.nanoTime();
            mission.run(Duration.ofMinutes(10)).requireCompleted();
            if (released.get() != agents) {
                throw new IllegalStateException(released.get() + " agents released, not " + agents);
            }
            return (lastReleased[0] - start) / 1e9;
        };
    }

    static String source(int agents) {
        String names = IntStream.range(0, agents).mapToObj(i -> "a" + i).collect(Collectors.joining(", "));
        return """
                import Default.xml as Default;
                Default %s = newAgent(Default);
                synchronous entry main (true) {
                  local int i = 1;
                }
                """.formatted(names);
    }
}
