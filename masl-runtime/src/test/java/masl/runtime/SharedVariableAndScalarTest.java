package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Shared variables (MASL §7) and scalar blocks (§6.2). */
@Timeout(120)
class SharedVariableAndScalarTest {

    /**
     * A synchronous main keeps all agents in one wave; the asynchronous child is one instruction
     * of it, in which they increment concurrently; the scalar child reports after the barrier at
     * the end of that instruction.
     * <pre>
     * synchronous entry main (true) {
     *   shared int n = 0;
     *   asynchronous entry count (true) { local int i; for (i = 0; i &lt; 1000; i++) n++; }
     *   scalar entry report (true) { record(n); }
     * }
     * </pre>
     */
    static final class Counter extends CompactProgram {
        static final int INCREMENTS = 1000;
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final SharedDeclaration<Integer> N = MAIN.declareShared("n", 0);
        static final EntryDefinition COUNT = MAIN.child("count", Mode.ASYNCHRONOUS);
        static final EntryDefinition REPORT = MAIN.child("report", Mode.SCALAR);

        private final ConcurrentLinkedQueue<Integer> reported;
        private int i;

        Counter(TestAgent self, ConcurrentLinkedQueue<Integer> reported) {
            super(self);
            this.reported = reported;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 12)) return; continue;
                    case 1: ctx.shared(N).initialise(() -> 0); pc = 2; continue;
                    case 2: if (!arrive(ctx, COUNT, true, 3, 7)) return; continue;
                    case 3: i = 0; pc = 4; continue;
                    case 4:
                        if (!(i < INCREMENTS)) {
                            pc = 6;
                            continue;
                        }
                        ctx.shared(N).getAndUpdate(n -> n + 1);
                        if (!step(ctx, 5)) return;
                        continue;
                    case 5: i++; pc = 4; if (!ctx.loopIteration()) return; continue;
                    case 6: if (!leave(ctx, COUNT, 7)) return; continue;
                    case 7: if (!endOfChild(ctx, COUNT, 8)) return; continue;
                    case 8: if (!arrive(ctx, REPORT, true, 9, 10)) return; continue;
                    case 9: reported.add(ctx.shared(N).get()); if (!leave(ctx, REPORT, 10)) return; continue;
                    case 10: if (!endOfChild(ctx, REPORT, 11)) return; continue;
                    case 11: if (!leave(ctx, MAIN, 12)) return; continue;
                    case 12: if (!endOf(ctx, MAIN.sequence(), 13)) return; continue;
                    case 13: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aSharedCounterIncrementedBy64AgentsAThousandTimesEachEndsAt64000(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            ConcurrentLinkedQueue<Integer> reported = new ConcurrentLinkedQueue<>();
            Missions.run(driver, Counter.MAIN, 64, self -> new Counter(self, reported));
            assertEquals(List.of(64 * Counter.INCREMENTS), List.copyOf(reported));
        }
    }

    /**
     * Two groups of four agents run block {@code p} one after the other, so it has two waves;
     * each group stays in {@code p} until all four are in. (A synchronous main keeps everyone in
     * one wave of main: an asynchronous one could end before the second group entered it.)
     * <pre>
     * synchronous entry main (true) {
     *   shared int inP = 0;
     *   while (.getProxyID() >= 4 &amp;&amp; (inP &lt; 4 || p.count > inP - 4)) {}   // until the first group left p
     *   asynchronous entry p (true) {
     *     inP++;
     *     while (inP &lt; (.getProxyID() &lt; 4 ? 4 : 8)) {}
     *     scalar entry once (true) { record(); }
     *   }
     * }
     * </pre>
     */
    static final class ScalarPerParentWave extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final SharedDeclaration<Integer> IN_P = MAIN.declareShared("inP", 0);
        static final EntryDefinition P = MAIN.child("p", Mode.ASYNCHRONOUS);
        static final EntryDefinition ONCE = P.child("once", Mode.SCALAR);

        private final AtomicInteger runs;

        ScalarPerParentWave(TestAgent self, AtomicInteger runs) {
            super(self);
            this.runs = runs;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 12)) return; continue;
                    case 1: ctx.shared(IN_P).initialise(() -> 0); pc = 2; continue;
                    case 2:
                        int inP = ctx.shared(IN_P).get();
                        boolean firstGroupBusy = inP < 4 || ctx.entry(P).count() > inP - 4;
                        if (!busyWait(ctx, id >= 4 && firstGroupBusy, 3)) return;
                        continue;
                    case 3: if (!arrive(ctx, P, true, 4, 10)) return; continue;
                    case 4: ctx.shared(IN_P).getAndUpdate(n -> n + 1); if (!step(ctx, 5)) return; continue;
                    case 5: if (!busyWait(ctx, ctx.shared(IN_P).get() < (id < 4 ? 4 : 8), 6)) return; continue;
                    case 6: if (!arrive(ctx, ONCE, true, 7, 8)) return; continue;
                    case 7: runs.incrementAndGet(); if (!leave(ctx, ONCE, 8)) return; continue;
                    case 8: if (!endOf(ctx, ONCE.sequence(), 9)) return; continue;
                    case 9: if (!leave(ctx, P, 10)) return; continue;
                    case 10: if (!endOfChild(ctx, P, 11)) return; continue;
                    case 11: if (!leave(ctx, MAIN, 12)) return; continue;
                    case 12: if (!endOf(ctx, MAIN.sequence(), 13)) return; continue;
                    case 13: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aScalarChildRunsOncePerWaveOfItsParent(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            AtomicInteger runs = new AtomicInteger();
            MemoryTrace trace = new MemoryTrace();
            Missions.run(driver, ScalarPerParentWave.MAIN, 8, self -> new ScalarPerParentWave(self, runs), trace);
            long parentWaves = trace.events(TraceEvent.WaveStarted.class).stream().filter(w -> w.block().equals("p")).count();
            assertEquals(2, parentWaves);
            assertEquals(2, runs.get());
            assertEquals(List.of(1, 2), trace.events(TraceEvent.WaveStarted.class).stream()
                    .filter(w -> w.block().equals("once")).map(TraceEvent.WaveStarted::wave).toList());
        }
    }

    /** {@code shared int s = .getProxyID() + 100;} is initialised once, by the first member. */
    static final class InitialisedOnce extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final SharedDeclaration<Integer> S = MAIN.declareShared("s", 0);

        private final AtomicInteger initialisations;
        private final ConcurrentLinkedQueue<Integer> seen;

        InitialisedOnce(TestAgent self, AtomicInteger initialisations, ConcurrentLinkedQueue<Integer> seen) {
            super(self);
            this.initialisations = initialisations;
            this.seen = seen;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 3)) return; continue;
                    case 1:
                        ctx.shared(S).initialise(() -> {
                            initialisations.incrementAndGet();
                            return self.getProxyID() + 100;
                        });
                        seen.add(ctx.shared(S).get());
                        if (!step(ctx, 2)) return;
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
    void aSharedVariableIsInitialisedOnceBeforeAnyMemberReadsIt(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            AtomicInteger initialisations = new AtomicInteger();
            ConcurrentLinkedQueue<Integer> seen = new ConcurrentLinkedQueue<>();
            Missions.run(driver, InitialisedOnce.MAIN, 8, self -> new InitialisedOnce(self, initialisations, seen));
            assertEquals(1, initialisations.get());
            assertEquals(8, seen.size());
            int value = seen.peek();
            seen.forEach(v -> assertEquals(value, v));
            assertEquals(true, value >= 100 && value < 108, () -> "value " + value);
        }
    }

    @Test
    void lockPoliciesFollowTheModes() {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        EntryDefinition scalar = main.child("s", Mode.SCALAR);
        EntryDefinition synchronous = main.child("y", Mode.SYNCHRONOUS);
        Mission mission = Mission.builder().main(main).build();
        assertEquals("unavailable", mission.entry(main).getLockPolicy());
        assertEquals("unavailable", mission.entry(scalar).getLockPolicy());
        assertEquals("free", mission.entry(synchronous).getLockPolicy());
        mission.entry(main).lock();
        mission.entry(synchronous).lock();
        assertEquals("unavailable", mission.entry(main).getLockPolicy());
        assertEquals("locked", mission.entry(synchronous).getLockPolicy());
        assertEquals(0, mission.entry(synchronous).count());
        assertEquals(List.of(), mission.entry(synchronous).getList());
    }
}
