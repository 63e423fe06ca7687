package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Map;
import java.util.concurrent.BrokenBarrierException;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
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
     * <pre>
     * synchronous entry main (true) {
     *   m0; m1; m2; (agent 0 breaks here, while the others arrive) m3; m4; m5;
     * }
     * </pre>
     */
    static final class LeaverInLockStep extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final int STEPS = 6;
        static final int BREAK_AT = 3;

        private final PhaseLog log;
        private final CyclicBarrier startLine;
        private int m;

        LeaverInLockStep(TestAgent self, PhaseLog log, CyclicBarrier startLine) {
            super(self);
            this.log = log;
            this.startLine = startLine;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 3)) return; continue;
                    case 1:
                        log.instruction(id, "m" + m);
                        if (m == BREAK_AT) {
                            meet(startLine);
                            if (id == 0) {
                                ctx.breakOut(MAIN);
                                pc = 3;
                                continue;
                            }
                        }
                        m++;
                        if (!step(ctx, m < STEPS ? 1 : 2)) return;
                        continue;
                    case 2: if (!leave(ctx, MAIN, 3)) return; continue;
                    case 3: if (!endOf(ctx, MAIN.sequence(), 4)) return; continue;
                    case 4: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMemberLeavingWhileTheOthersArriveTripsEachPhaseOnceWithoutIt(Driver driver) {
        for (int run = 0; run < RUNS; run++) {
            PhaseLog log = new PhaseLog("main", Trace.NONE);
            CyclicBarrier startLine = startLine(driver, AGENTS);
            Missions.run(driver, LeaverInLockStep.MAIN, AGENTS, self -> new LeaverInLockStep(self, log, startLine), log);
            assertEquals(List.of(4, 4, 4, 3, 3, 3), tripSizes(log), "run " + run);
            assertEquals(List.of(), log.lockStepViolations());
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int agent = 0; agent < AGENTS; agent++) {
                int last = agent == 0 ? LeaverInLockStep.BREAK_AT : LeaverInLockStep.STEPS - 1;
                for (int k = 0; k <= last; k++) {
                    assertEquals(k, phases.get(agent).get("m" + k), "run " + run + ", agent " + agent + " m" + k);
                }
            }
        }
    }

    /**
     * <pre>
     * synchronous entry main (true) {
     *   scalar entry setup (true) { child.lock(); }
     *   synchronous entry child (.getProxyID() == 0) { c0; c1; c2; }      // agent 0 held while the others arrive
     *   if (.getProxyID() != 0) { m0; m1; m2; m3; m4; m5; }             // agent 1 releases child in m3
     * }
     * </pre>
     */
    static final class HeldAndReleased extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final EntryDefinition SETUP = MAIN.child("setup", Mode.SCALAR);
        static final EntryDefinition CHILD = MAIN.child("child", Mode.SYNCHRONOUS);
        static final int RELEASE_AT = 3;

        private final PhaseLog log;
        private final CyclicBarrier holdLine;
        private final CyclicBarrier releaseLine;
        private int c;
        private int m;

        HeldAndReleased(TestAgent self, PhaseLog log, CyclicBarrier holdLine, CyclicBarrier releaseLine) {
            super(self);
            this.log = log;
            this.holdLine = holdLine;
            this.releaseLine = releaseLine;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 10)) return; continue;
                    case 1: if (!arrive(ctx, SETUP, true, 2, 3)) return; continue;
                    case 2: ctx.entry(CHILD).lock(); if (!leave(ctx, SETUP, 3)) return; continue;
                    case 3: if (!endOfChild(ctx, SETUP, 4)) return; continue;
                    case 4: meet(holdLine); if (!arrive(ctx, CHILD, id == 0, 5, 7)) return; continue;
                    case 5: log.instruction(id, "c" + c++); if (!step(ctx, c < 3 ? 5 : 6)) return; continue;
                    case 6: if (!leave(ctx, CHILD, 7)) return; continue;
                    case 7: if (!endOf(ctx, CHILD.sequence(), 8)) return; continue;
                    case 8:
                        if (id == 0) {
                            pc = 9;
                            continue;
                        }
                        log.instruction(id, "m" + m);
                        if (m == RELEASE_AT) {
                            meet(releaseLine);
                            if (id == 1) {
                                ctx.entry(CHILD).release();
                            }
                        }
                        m++;
                        if (!step(ctx, m < 6 ? 8 : 9)) return;
                        continue;
                    case 9: if (!leave(ctx, MAIN, 10)) return; continue;
                    case 10: if (!endOf(ctx, MAIN.sequence(), 11)) return; continue;
                    case 11: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMemberHeldAndReleasedWhileTheOthersArriveIsWaitedForExactlyWhileItTakesPart(Driver driver) {
        for (int run = 0; run < RUNS; run++) {
            PhaseLog log = new PhaseLog("main", Trace.NONE);
            CyclicBarrier holdLine = startLine(driver, AGENTS);
            CyclicBarrier releaseLine = startLine(driver, AGENTS - 1);
            Missions.run(driver, HeldAndReleased.MAIN, AGENTS,
                    self -> new HeldAndReleased(self, log, holdLine, releaseLine), log);
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
