package masl.bench;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicLong;
import masl.runtime.AgentContext;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.Mode;
import masl.runtime.PoolScheduler;

/**
 * MASL's side of the invocation benchmark (issue 13, item 2): pairs of agents in one mission on the
 * default pool, each pinger invoking its pong's primitive {@code nop} synchronously, again and
 * again, as the JADE pingers of {@code AclPingPong} do; round trips completed within the window
 * (after the warm-up) are counted. The pongs skip {@code main} and finish, so each invocation is
 * served on the pong's behalf (MASL §5), as a JADE pong blocked on its message queue serves a
 * request.
 *
 * <p>The program is written by hand as the translator would generate this MASL
 * (generated-code-contract.md §3.11, §8.1), the external invocation an instruction with its step
 * boundary:
 * <pre>
 * asynchronous entry main (.getProxyID() % 2 == 0) {
 *   while (playing) { pong.nop(); }
 * }
 * </pre>
 */
final class MaslPingPong {

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);

    private MaslPingPong() {
    }

    /** Round trips per second of {@code pairs} pairs playing all at once. */
    static double measure(int pairs, Duration warmUp, Duration window) throws InterruptedException {
        Clock clock = new Clock(warmUp, window);
        Mission.Builder builder = Mission.builder().main(MAIN).scheduler(new PoolScheduler()).journal(new StringBuilder());
        for (int pair = 0; pair < pairs; pair++) {
            Pong pong = new Pong();
            builder.agent("ping" + pair, new Pong(), self -> new Player(pong, clock));
            builder.agent("pong" + pair, pong, self -> new Player(null, clock));
        }
        Mission mission = builder.build();
        clock.start();
        mission.run(warmUp.plus(window).plusMinutes(1)).requireCompleted();
        return clock.roundTrips.get() / (window.toNanos() / 1e9);
    }

    /** The timing all pingers of one measurement share, and their count. */
    private static final class Clock {
        final AtomicLong roundTrips = new AtomicLong();
        private final Duration warmUp;
        private final Duration window;
        private volatile long windowStart;
        private volatile long end;

        Clock(Duration warmUp, Duration window) {
            this.warmUp = warmUp;
            this.window = window;
        }

        void start() {
            windowStart = System.nanoTime() + warmUp.toNanos();
            end = windowStart + window.toNanos();
        }
    }

    /** An agent type with one primitive that does nothing. */
    public static final class Pong extends AgentImplementation {
        public Object nop() {
            return null;
        }
    }

    /** The program above: a pinger plays with its pong; a pong (no pong of its own) skips main and finishes. */
    private static final class Player extends AgentProgram {
        private final Pong pong;
        private final Clock clock;
        private CompletableFuture<Object> call;
        private long callStarted;
        private long counted;

        Player(Pong pong, Clock clock) {
            this.pong = pong;
            this.clock = clock;
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: // asynchronous entry main (.getProxyID() % 2 == 0)
                        pc = 1;
                        switch (ctx.enter(MAIN, pong != null)) {
                            case SKIPPED -> { pc = 5; continue; }
                            case WAITING -> { return; }
                            case ENTERED -> { }
                        }
                    case 1: // while (playing)
                        callStarted = System.nanoTime();
                        if (callStarted >= clock.end) {
                            clock.roundTrips.addAndGet(counted);
                            pc = 4;
                            continue;
                        }
                        // pong.nop();
                        call = ctx.invoke(pong, "nop", null, pong::nop);
                        pc = 2;
                        if (!ctx.await(call)) return;
                    case 2:
                        call.join();
                        if (callStarted >= clock.windowStart && System.nanoTime() < clock.end) {
                            counted++;
                        }
                        pc = 3;
                        if (!ctx.stepBoundary()) return;
                    case 3:
                        pc = 1;
                        if (!ctx.loopIteration()) return;
                        continue;
                    case 4: // end of main
                        pc = 5;
                        if (!ctx.leave(MAIN)) return;
                    case 5: // after main
                        pc = 6;
                        if (!ctx.endOfSequence(MAIN.sequence())) return;
                    case 6:
                        ctx.finish();
                        return;
                    default:
                        throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }
}
