package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BrokenBarrierException;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.PhaseLog;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Lock-free arrivals at a synchronisation barrier racing the membership changes that take the
 * coordinator's lock: a member leaving, a member held by a child's entry barrier, a member released
 * into the domain. With a thread per agent, the racers first meet at a {@link CyclicBarrier}, so
 * that the change and the arrivals start at the same instant; the other drivers race as they come.
 * Every run must trip each phase exactly once, with exactly the agents in lock-step then.
 */
@Timeout(60)
@Tag("slow")
class BarrierRaceTest {

    /** Missions per driver: the race is decided in a few nanoseconds, so it takes many runs to see both sides. */
    private static final int RUNS = Math.max(1000, Missions.REPETITIONS);
    private static final int AGENTS = 4;

    /** With a thread per agent, the racers meet before racing; the pool's agents cannot block their workers. */
    private static CyclicBarrier startLine(Driver driver, int racers) {
        return driver == Driver.THREADS ? new CyclicBarrier(racers) : null;
    }

    private static void meet(CyclicBarrier startLine) {
        if (startLine == null) {
            return;
        }
        try {
            startLine.await(10, TimeUnit.SECONDS);
        } catch (InterruptedException | BrokenBarrierException | TimeoutException e) {
            throw new IllegalStateException("racers did not meet", e);
        }
    }

    /**
     * An agent whose instructions go to a {@link PhaseLog} and whose {@code signal(k)}, of zero
     * duration, meets the {@code k}-th start line (if any) just before its racing step.
     */
    private static final class Racer extends TestAgent {
        private final List<CyclicBarrier> startLines;

        Racer(PhaseLog log, List<CyclicBarrier> startLines) {
            super(log);
            this.startLines = startLines;
        }

        @Override
        public int signal(int line) {
            meet(startLines.get(line));
            return line;
        }
    }

    /** Agent 0 breaks before m4, while the others arrive at m4's barrier. */
    private static final MaslProgram LEAVER_IN_LOCK_STEP = MaslProgram.of("leaver.masl", AGENTS, """
            synchronous entry main (true) {
              local int m = 0;
              for (m = 0; m < 6; m++) {
                if (m == 4) { .signal(0); if (.getProxyID() == 0) break; }
                .instruction("m" + m);
              }
            }
            """);
    private static final int STEPS = 6;
    private static final int LAST_BEFORE_BREAK = 3;

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMemberLeavingWhileTheOthersArriveTripsEachPhaseOnceWithoutIt(Driver driver) {
        for (int run = 0; run < RUNS; run++) {
            PhaseLog log = new PhaseLog("main", Trace.NONE);
            List<CyclicBarrier> startLines = Collections.singletonList(startLine(driver, AGENTS));
            LEAVER_IN_LOCK_STEP.run(driver.newScheduler(), log, () -> new Racer(log, startLines));
            assertEquals(List.of(4, 4, 4, 4, 3, 3), tripSizes(log), "run " + run);
            assertEquals(List.of(), log.lockStepViolations());
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int agent = 0; agent < AGENTS; agent++) {
                int last = agent == 0 ? LAST_BEFORE_BREAK : STEPS - 1;
                for (int k = 0; k <= last; k++) {
                    assertEquals(k, phases.get(agent).get("m" + k), "run " + run + ", agent " + agent + " m" + k);
                }
            }
        }
    }

    /**
     * Agent 0 is held by {@code child}'s entry barrier while the others arrive; agent 1 releases
     * it before m3, racing the others' arrivals at m3's barrier.
     */
    private static final MaslProgram HELD_AND_RELEASED = MaslProgram.of("held.masl", AGENTS, """
            Entry child;
            synchronous entry main (true) {
              local int c = 0;
              local int m = 0;
              scalar entry setup (true) { child.lock(); }
              .signal(0);
              synchronous entry child (.getProxyID() == 0) { for (c = 0; c < 3; c++) .instruction("c" + c); }
              if (.getProxyID() != 0) {
                for (m = 0; m < 6; m++) {
                  if (m == 3) { .signal(1); if (.getProxyID() == 1) child.release(); }
                  .instruction("m" + m);
                }
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMemberHeldAndReleasedWhileTheOthersArriveIsWaitedForExactlyWhileItTakesPart(Driver driver) {
        for (int run = 0; run < RUNS; run++) {
            PhaseLog log = new PhaseLog("main", Trace.NONE);
            List<CyclicBarrier> startLines = Arrays.asList(startLine(driver, AGENTS), startLine(driver, AGENTS - 1));
            HELD_AND_RELEASED.run(driver.newScheduler(), log, () -> new Racer(log, startLines));
            // setup, one instruction, with all four; skipping child takes no step; m0 … m2 without
            // agent 0, held; released during m3, it runs c0 … c2 in lock-step with m3 … m5.
            assertEquals(List.of(4, 3, 3, 3, 4, 4, 4), tripSizes(log), "run " + run);
            assertEquals(List.of(), log.lockStepViolations());
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int k = 0; k < 3; k++) {
                assertEquals(4 + k, phases.get(0).get("c" + k), "run " + run + ", agent 0 c" + k);
            }
            for (int agent = 1; agent < AGENTS; agent++) {
                for (int k = 0; k < 6; k++) {
                    assertEquals(1 + k, phases.get(agent).get("m" + k), "run " + run + ", agent " + agent + " m" + k);
                }
            }
        }
    }

    private static List<Integer> tripSizes(PhaseLog log) {
        return log.trips().stream().map(TraceEvent.BarrierTripped::agents).toList();
    }
}
