package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;
import masl.runtime.entry.Entry;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.PhaseLog;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Synchronous blocks (MASL §6.3–§6.5): barriers with dynamic membership, entry and exit barriers, waves. */
@Timeout(120)
class SynchronousBlockTest {

    /**
     * <pre>
     * synchronous entry main (true) {
     *   synchronous entry child (.getProxyID() % 2 == 0) { c0; c1; c2; c3; c4; }
     *   m0; m1; … m9;
     * }
     * </pre>
     * or, with {@code breakAfter} = 3, {@code { c0; c1; c2; break; … }}.
     */
    static final class ChildInLockStep extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final EntryDefinition CHILD = MAIN.child("child", Mode.SYNCHRONOUS);

        private final PhaseLog log;
        private final int breakAfter;
        private int c;
        private int m;

        ChildInLockStep(TestAgent self, PhaseLog log, int breakAfter) {
            super(self);
            this.log = log;
            this.breakAfter = breakAfter;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 7)) return; continue;
                    case 1: if (!arrive(ctx, CHILD, id % 2 == 0, 2, 4)) return; continue;
                    case 2: log.instruction(id, "c" + c++); if (!step(ctx, c < 5 && c != breakAfter ? 2 : 3)) return; continue;
                    case 3:
                        if (c == breakAfter) {
                            ctx.breakOut(CHILD);
                            pc = 4;
                            continue;
                        }
                        if (!leave(ctx, CHILD, 4)) return;
                        continue;
                    case 4: if (!endOf(ctx, CHILD.sequence(), 5)) return; continue;
                    case 5: log.instruction(id, "m" + m++); if (!step(ctx, m < 10 ? 5 : 6)) return; continue;
                    case 6: if (!leave(ctx, MAIN, 7)) return; continue;
                    case 7: if (!endOf(ctx, MAIN.sequence(), 8)) return; continue;
                    case 8: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void synchronousChildKeepsLockStepWithItsParentsOtherMembers(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            PhaseLog log = new PhaseLog("main", Trace.NONE);
            Missions.run(driver, ChildInLockStep.MAIN, 6, self -> new ChildInLockStep(self, log, -1), log);
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int agent = 0; agent < 6; agent++) {
                Map<String, Integer> phase = phases.get(agent);
                if (agent % 2 == 0) {
                    // Members of the child: c0 … c4 in phases 0 … 4, then m0 … m9 in phases 5 … 14.
                    assertEquals(15, phase.size());
                    for (int k = 0; k < 5; k++) {
                        assertEquals(k, phase.get("c" + k), "agent " + agent + " c" + k);
                    }
                    for (int k = 0; k < 10; k++) {
                        assertEquals(5 + k, phase.get("m" + k), "agent " + agent + " m" + k);
                    }
                } else {
                    // Skippers do not wait for a synchronous child (§6.4): m0 pairs with c0.
                    assertEquals(10, phase.size());
                    for (int k = 0; k < 10; k++) {
                        assertEquals(k, phase.get("m" + k), "agent " + agent + " m" + k);
                    }
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anAgentBreakingOutOfASynchronousChildKeepsPaceWithoutAnExtraBarrier(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            PhaseLog log = new PhaseLog("main", Trace.NONE);
            Missions.run(driver, ChildInLockStep.MAIN, 6, self -> new ChildInLockStep(self, log, 3), log);
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int agent = 0; agent < 6; agent++) {
                Map<String, Integer> phase = phases.get(agent);
                int firstMainPhase = agent % 2 == 0 ? 3 : 0;
                for (int k = 0; agent % 2 == 0 && k < 3; k++) {
                    assertEquals(k, phase.get("c" + k), "agent " + agent + " c" + k);
                }
                for (int k = 0; k < 10; k++) {
                    assertEquals(firstMainPhase + k, phase.get("m" + k), "agent " + agent + " m" + k);
                }
            }
        }
    }

    /**
     * <pre>
     * synchronous entry main (true) {
     *   scalar entry setup (true) { child.lock(); }
     *   synchronous entry child (.getProxyID() % 2 == 0) { c0; c1; c2; }
     *   if (.getProxyID() % 2 == 1) { m0; m1; m2; m3; m4 (agent 1 also runs child.release()); }
     * }
     * </pre>
     */
    static final class HeldAtChildEntry extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final EntryDefinition SETUP = MAIN.child("setup", Mode.SCALAR);
        static final EntryDefinition CHILD = MAIN.child("child", Mode.SYNCHRONOUS);

        private int c;
        private int m;

        HeldAtChildEntry(TestAgent self) {
            super(self);
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
                    case 4: if (!arrive(ctx, CHILD, id % 2 == 0, 5, 7)) return; continue;
                    case 5: self.nop(); c++; if (!step(ctx, c < 3 ? 5 : 6)) return; continue;
                    case 6: if (!leave(ctx, CHILD, 7)) return; continue;
                    case 7: if (!endOf(ctx, CHILD.sequence(), 8)) return; continue;
                    case 8:
                        if (id % 2 == 0) {
                            pc = 9;
                            continue;
                        }
                        if (id == 1 && m == 4) {
                            ctx.entry(CHILD).release();
                        }
                        m++;
                        if (!step(ctx, m < 5 ? 8 : 9)) return;
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
    void agentsHeldAtAChildsEntryBarrierDoNotHoldTheParentsBarrier(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            Missions.run(driver, HeldAtChildEntry.MAIN, 6, HeldAtChildEntry::new, trace);
            List<TraceEvent> events = trace.events();
            int lastHeld = lastIndex(events, e -> e instanceof TraceEvent.WaitingIn w && w.block().equals("child"));
            int firstReleased = firstIndex(events, e -> e instanceof TraceEvent.Released r && r.block().equals("child"));
            List<TraceEvent.BarrierTripped> tripsWhileHeld = new ArrayList<>();
            for (TraceEvent event : events.subList(lastHeld, firstReleased)) {
                if (event instanceof TraceEvent.BarrierTripped trip) {
                    tripsWhileHeld.add(trip);
                }
            }
            // The odd agents' m0 … m3 trip without the three held agents (skipping child takes no step).
            assertEquals(4, tripsWhileHeld.size(), events::toString);
            tripsWhileHeld.forEach(trip -> assertEquals(3, trip.agents(), events::toString));
        }
    }

    /**
     * <pre>
     * synchronous entry main (true) {
     *   synchronous entry child (true) {
     *     local boolean reelected = false;
     *     .nop();
     *     if (.getProxyID() == 0 &amp;&amp; !reelected) { reelected = true; reelect; }
     *     if (.getProxyID() == 1) { while (child.getWaitingInCount() == 0) {} child.release(); }
     *     .nop();
     *   }
     * }
     * </pre>
     */
    static final class ReelectInSynchronousBlock extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final EntryDefinition CHILD = MAIN.child("child", Mode.SYNCHRONOUS);

        private boolean keepChildLocals;
        private boolean reelected;

        ReelectInSynchronousBlock(TestAgent self) {
            super(self);
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 10)) return; continue;
                    case 1:
                        if (!arrive(ctx, CHILD, true, 2, 8)) return;
                        if (pc == 8) {
                            keepChildLocals = false;
                        }
                        continue;
                    case 2:
                        if (!keepChildLocals) {
                            reelected = false;
                        }
                        keepChildLocals = false;
                        self.nop();
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3:
                        if (id == 0 && !reelected) {
                            reelected = true;
                            ctx.reelect(CHILD);
                            keepChildLocals = true;
                            pc = 1;
                            continue;
                        }
                        pc = id == 1 ? 4 : 6;
                        continue;
                    case 4:
                        if (!busyWait(ctx, ctx.entry(CHILD).getWaitingInCount() == 0, 5)) return;
                        continue;
                    case 5: ctx.entry(CHILD).release(); pc = 6; continue;
                    case 6: self.nop(); if (!step(ctx, 7)) return; continue;
                    case 7: if (!leave(ctx, CHILD, 8)) return; continue;
                    case 8: if (!endOf(ctx, CHILD.sequence(), 9)) return; continue;
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
    void reelectLeavesWithoutExitBarrierAndArrivesAgainAsANewArrival(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            Missions.run(driver, ReelectInSynchronousBlock.MAIN, 2, ReelectInSynchronousBlock::new, trace);
            List<String> agent0 = new ArrayList<>();
            for (TraceEvent event : trace.events()) {
                if (event instanceof TraceEvent.WaitingIn e && e.agent() == 0 && e.block().equals("child")) {
                    agent0.add("waiting-in");
                } else if (event instanceof TraceEvent.Released e && e.agent() == 0 && e.block().equals("child")) {
                    agent0.add("released into " + e.wave());
                } else if (event instanceof TraceEvent.Left e && e.agent() == 0 && e.block().equals("child")) {
                    agent0.add("left by " + e.cause());
                } else if (event instanceof TraceEvent.WaitingOut e && e.agent() == 0) {
                    agent0.add("waiting-out of " + e.block());
                }
            }
            // The second arrival meets the entry barrier locked by the first wave, is released
            // into that wave (agent 1 is still in it), and its local survived the reelect.
            assertEquals(List.of("waiting-in", "released into 1", "left by REELECT", "waiting-in", "released into 1",
                    "waiting-out of child", "left by END", "waiting-out of main"), agent0);
        }
    }

    /**
     * Agents join a locked synchronous block one by one, as a keeper releases each as soon as it
     * waits, so they join waves in progress; member {@code k} runs {@code 2k + 1} instructions and
     * leaves by its end (even k) or by {@code break} (odd k).
     */
    static final class JoinAndLeave extends CompactProgram {
        static final int MEMBERS = 8;
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final SharedDeclaration<Integer> FINISHED = MAIN.declareShared("finished", 0);
        static final EntryDefinition SETUP = MAIN.child("setup", Mode.SCALAR);
        static final ESequence KEEP_GROUP = MAIN.newSequence();
        static final EntryDefinition KEEP = KEEP_GROUP.block("keep", Mode.ASYNCHRONOUS);
        static final EntryDefinition GROUP = KEEP_GROUP.block("group", Mode.SYNCHRONOUS);

        private final PhaseLog log;
        private int k;

        JoinAndLeave(TestAgent self, PhaseLog log) {
            super(self);
            this.log = log;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            Entry group = ctx.entry(GROUP);
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 15)) return; continue;
                    case 1:
                        ctx.shared(FINISHED).initialise(() -> 0);
                        if (!arrive(ctx, SETUP, true, 2, 3)) return;
                        continue;
                    case 2: group.lock(); if (!leave(ctx, SETUP, 3)) return; continue;
                    case 3: if (!endOf(ctx, SETUP.sequence(), 4)) return; continue;
                    case 4: if (!busyWait(ctx, Objects.equals(group.getLockPolicy(), "free"), 5)) return; continue;
                    case 5: if (!arrive(ctx, KEEP, id == 0, 6, 8)) return; continue;
                    case 6:
                        if (!(ctx.shared(FINISHED).get() < MEMBERS)) {
                            pc = 7;
                            continue;
                        }
                        if (group.getWaitingInCount() > 0) {
                            group.release(1);
                        }
                        if (!ctx.busyWaitIteration()) return;
                        continue;
                    case 7: if (!leave(ctx, KEEP, 8)) return; continue;
                    case 8: if (!arrive(ctx, GROUP, id != 0, 9, 12)) return; continue;
                    case 9: log.instruction(id, "g" + k++); if (!step(ctx, k < 2 * id + 1 ? 9 : 10)) return; continue;
                    case 10:
                        if (id % 2 == 1) {
                            ctx.breakOut(GROUP);
                            pc = 12;
                            continue;
                        }
                        pc = 11;
                        continue;
                    case 11: if (!leave(ctx, GROUP, 12)) return; continue;
                    case 12: if (!endOf(ctx, KEEP_GROUP, 13)) return; continue;
                    case 13:
                        if (id != 0) {
                            ctx.shared(FINISHED).getAndUpdate(n -> n + 1);
                        }
                        if (!step(ctx, 14)) return;
                        continue;
                    case 14: if (!leave(ctx, MAIN, 15)) return; continue;
                    case 15: if (!endOf(ctx, MAIN.sequence(), 16)) return; continue;
                    case 16: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void agentsJoiningAndLeavingMidWaveNeverDeadlockNorTripWithoutAMember(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            PhaseLog log = new PhaseLog("group", Trace.NONE);
            Missions.run(driver, JoinAndLeave.MAIN, JoinAndLeave.MEMBERS + 1, self -> new JoinAndLeave(self, log), log);
            assertEquals(List.of(), log.lockStepViolations());
            log.trips().forEach(trip -> assertTrue(trip.agents() > 0, trip::toString));
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int member = 1; member <= JoinAndLeave.MEMBERS; member++) {
                assertEquals(2 * member + 1, phases.get(member).size(), "instructions of member " + member);
            }
        }
    }

    /**
     * A keeper releases members of a locked block: {@code release(n)} first, then all; or one, and
     * the next one only once the block is empty again. Members record their shared variable.
     */
    static final class Gate extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final EntryDefinition SETUP = MAIN.child("setup", Mode.SCALAR);
        static final ESequence KEEP_GATE = MAIN.newSequence();
        static final EntryDefinition KEEP = KEEP_GATE.block("keep", Mode.ASYNCHRONOUS);
        static final EntryDefinition GATE = KEEP_GATE.block("gate", Mode.SYNCHRONOUS);
        static final SharedDeclaration<Integer> GATE_S = GATE.declareShared("s", 0);

        private final boolean oneWaveEach;
        private final AtomicInteger waitingAfterRelease;
        private final ConcurrentLinkedQueue<Integer> seen;

        Gate(TestAgent self, boolean oneWaveEach, AtomicInteger waitingAfterRelease, ConcurrentLinkedQueue<Integer> seen) {
            super(self);
            this.oneWaveEach = oneWaveEach;
            this.waitingAfterRelease = waitingAfterRelease;
            this.seen = seen;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            Entry gate = ctx.entry(GATE);
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 16)) return; continue;
                    case 1: if (!arrive(ctx, SETUP, true, 2, 3)) return; continue;
                    case 2: gate.lock(); if (!leave(ctx, SETUP, 3)) return; continue;
                    case 3: if (!endOf(ctx, SETUP.sequence(), 4)) return; continue;
                    case 4: if (!busyWait(ctx, Objects.equals(gate.getLockPolicy(), "free"), 5)) return; continue;
                    case 5: if (!arrive(ctx, KEEP, id == 0, 6, 11)) return; continue;
                    case 6: if (!busyWait(ctx, gate.getWaitingInCount() < waiting(), 7)) return; continue;
                    case 7:
                        if (oneWaveEach) {
                            gate.release(1);
                            pc = 8;
                            continue;
                        }
                        gate.release(2);
                        waitingAfterRelease.set(gate.getWaitingInCount());
                        gate.release();
                        pc = 10;
                        continue;
                    case 8:
                        // Until the first member's wave is over: only the second agent is left, waiting.
                        if (!busyWait(ctx, gate.count() > 1, 9)) return;
                        continue;
                    case 9: gate.release(1); pc = 10; continue;
                    case 10: if (!leave(ctx, KEEP, 11)) return; continue;
                    case 11: if (!arrive(ctx, GATE, id != 0, 12, 14)) return; continue;
                    case 12:
                        ctx.shared(GATE_S).initialise(() -> 0);
                        seen.add(ctx.shared(GATE_S).update(s -> s + 1));
                        if (!step(ctx, 13)) return;
                        continue;
                    case 13: if (!leave(ctx, GATE, 14)) return; continue;
                    case 14: if (!endOf(ctx, KEEP_GATE, 15)) return; continue;
                    case 15: if (!leave(ctx, MAIN, 16)) return; continue;
                    case 16: if (!endOf(ctx, MAIN.sequence(), 17)) return; continue;
                    case 17: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }

        private int waiting() {
            return oneWaveEach ? 2 : 6;
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void releaseOfNAdmitsExactlyTheNEarliestArrivals(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            AtomicInteger waitingAfterRelease = new AtomicInteger(-1);
            ConcurrentLinkedQueue<Integer> seen = new ConcurrentLinkedQueue<>();
            Missions.run(driver, Gate.MAIN, 7, self -> new Gate(self, false, waitingAfterRelease, seen), trace);
            assertEquals(4, waitingAfterRelease.get());
            List<Integer> arrivals = trace.events(TraceEvent.WaitingIn.class).stream()
                    .filter(w -> w.block().equals("gate")).map(TraceEvent.WaitingIn::agent).toList();
            List<Integer> released = trace.events(TraceEvent.Released.class).stream()
                    .filter(r -> r.block().equals("gate")).map(TraceEvent.Released::agent).toList();
            assertEquals(6, released.size());
            assertEquals(arrivals.subList(0, 2), released.subList(0, 2));
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void releaseJustAfterAWaveEndsStartsANewWaveWithFreshSharedVariables(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            ConcurrentLinkedQueue<Integer> seen = new ConcurrentLinkedQueue<>();
            Missions.run(driver, Gate.MAIN, 3, self -> new Gate(self, true, new AtomicInteger(), seen), trace);
            assertEquals(List.of(1, 1), new ArrayList<>(seen));
            List<String> waves = new ArrayList<>();
            for (TraceEvent event : trace.events()) {
                if (event instanceof TraceEvent.WaveStarted w && w.block().equals("gate")) {
                    waves.add("start " + w.wave());
                } else if (event instanceof TraceEvent.WaveEnded w && w.block().equals("gate")) {
                    waves.add("end " + w.wave());
                } else if (event instanceof TraceEvent.Released r && r.block().equals("gate")) {
                    waves.add("released into " + r.wave());
                }
            }
            assertEquals(List.of("start 1", "released into 1", "end 1", "start 2", "released into 2", "end 2"), waves);
        }
    }

    /** {@code synchronous entry main (true) { for (i = 0; i < 1000; i++) .nop(); }} */
    static final class ThousandSteps extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final int STEPS = 1000;

        private int i;

        ThousandSteps(TestAgent self) {
            super(self);
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 5)) return; continue;
                    case 1: i = 0; pc = 2; continue;
                    case 2:
                        if (!(i < STEPS)) {
                            pc = 4;
                            continue;
                        }
                        self.nop();
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3: i++; pc = 2; if (!ctx.loopIteration()) return; continue;
                    case 4: if (!leave(ctx, MAIN, 5)) return; continue;
                    case 5: if (!endOf(ctx, MAIN.sequence(), 6)) return; continue;
                    case 6: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /** The scalable model's reason to be: one thread per agent would take about 20 s here. */
    @ParameterizedTest
    @EnumSource(value = Driver.class, names = {"POOL", "SINGLE_WORKER"})
    void aThousandAgentsRunAThousandLockStepSteps(Driver driver) {
        AtomicInteger trips = new AtomicInteger();
        AtomicInteger largestTrip = new AtomicInteger();
        Missions.run(driver, ThousandSteps.MAIN, 1000, ThousandSteps::new, event -> {
            if (event instanceof TraceEvent.BarrierTripped trip) {
                trips.incrementAndGet();
                largestTrip.accumulateAndGet(trip.agents(), Math::max);
            }
        });
        assertEquals(ThousandSteps.STEPS, trips.get());
        assertEquals(1000, largestTrip.get());
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void lockStepStepsAtAScaleThreadsCanRun(Driver driver) {
        for (int run = 0; run < 5; run++) {
            AtomicInteger trips = new AtomicInteger();
            Missions.run(driver, ThousandSteps.MAIN, 50, ThousandSteps::new, event -> {
                if (event instanceof TraceEvent.BarrierTripped trip && trip.agents() == 50) {
                    trips.incrementAndGet();
                }
            });
            assertEquals(ThousandSteps.STEPS, trips.get());
        }
    }

    private interface EventTest {
        boolean test(TraceEvent event);
    }

    private static int firstIndex(List<TraceEvent> events, EventTest test) {
        for (int i = 0; i < events.size(); i++) {
            if (test.test(events.get(i))) {
                return i;
            }
        }
        throw new AssertionError("no such event in " + events);
    }

    private static int lastIndex(List<TraceEvent> events, EventTest test) {
        for (int i = events.size() - 1; i >= 0; i--) {
            if (test.test(events.get(i))) {
                return i;
            }
        }
        throw new AssertionError("no such event in " + events);
    }
}
