package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.PhaseLog;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Who perceives an emission (MASL §8), and events between agents: local and shared events, nested
 * members, concurrent emitters, system events, an abort by event, events in lock-step.
 */
@Timeout(180)
class EventDeliveryTest {

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local event mine;
     *   shared int emitted = 0;
     *   emitWithMessage(mine, .getProxyID());
     *   emitted++;
     *   while (emitted &lt; 3) {}
     *   .nop();
     *   react (mine) { .logln(.getProxyID() + " heard " + getMessageFromEvent(mine)); resume; }
     * }
     * </pre>
     * Every emission precedes the last {@code emitted++}, which precedes everyone's {@code .nop()}:
     * an occurrence wrongly delivered to another agent would be reacted to at that boundary at the latest.
     */
    static final class LocalOnly extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event MINE = MAIN.declareLocalEvent("mine");
        static final SharedDeclaration<Integer> EMITTED = MAIN.declareShared("emitted", 0);
        static final Reaction MAIN_MINE = MAIN.react(MINE);

        LocalOnly(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 20;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 6)) return; continue;
                    case 1:
                        ctx.shared(EMITTED).initialise(() -> 0);
                        ctx.emit(MINE, String.valueOf(self.getProxyID()));
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2: ctx.shared(EMITTED).getAndUpdate(n -> n + 1); if (!step(ctx, 3)) return; continue;
                    case 3: if (!busyWait(ctx, ctx.shared(EMITTED).get() < 3, 4)) return; continue;
                    case 4: self.nop(); if (!step(ctx, 5)) return; continue;
                    case 5: if (!leave(ctx, MAIN, 6)) return; continue;
                    case 6: if (!endOf(ctx, MAIN.sequence(), 7)) return; continue;
                    case 7: ctx.finish(); return;
                    case 20:
                        self.logln(self.getProxyID() + " heard " + ctx.messageOf(MINE));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aLocalEventIsPerceivedByItsEmitterOnly(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = Missions.run(driver, LocalOnly.MAIN, 3, LocalOnly::new, trace).journal();
            assertEquals(List.of("0 heard 0", "1 heard 1", "2 heard 2"), ReactionRulesTest.sortedLines(journal));
            assertTrue(trace.events(TraceEvent.EventEmitted.class).stream().allMatch(e -> e.receivers() == 1));
        }
    }

    /**
     * Agent 2 stays outside {@code team}, agent 0 is in a block nested in it, agent 1 emits:
     * <pre>
     * asynchronous entry main (true) {
     *   shared int ready = 0;
     *   shared int done = 0;
     *   asynchronous entry team (.getProxyID() != 2) {
     *     shared event hello;
     *     asynchronous entry deep (.getProxyID() == 0) {
     *       ready++;
     *       while (done == 0) {}
     *       .nop();
     *     }
     *     if (.getProxyID() == 1) {
     *       while (ready &lt; 2) {}
     *       emitWithMessage(hello, "hi");
     *       done = 1;
     *     }
     *     react (hello) { .logln(.getProxyID() + " heard " + getMessageFromEvent(hello)); resume; }
     *   }
     *   if (.getProxyID() == 2) {
     *     ready++;
     *     while (done == 0) {}
     *     .nop();
     *   }
     *   react (default) { .logln(.getProxyID() + " outside heard"); resume; }
     * }
     * </pre>
     */
    static final class SharedToNested extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final SharedDeclaration<Integer> READY = MAIN.declareShared("ready", 0);
        static final SharedDeclaration<Integer> DONE = MAIN.declareShared("done", 0);
        static final EntryDefinition TEAM = MAIN.child("team", Mode.ASYNCHRONOUS);
        static final Event HELLO = TEAM.declareSharedEvent("hello");
        static final EntryDefinition DEEP = TEAM.child("deep", Mode.ASYNCHRONOUS);
        static final Reaction TEAM_HELLO = TEAM.react(HELLO);
        static final Reaction MAIN_DEFAULT = MAIN.reactToDefault();

        SharedToNested(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == TEAM_HELLO ? 30 : 31;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 20)) return; continue;
                    case 1:
                        ctx.shared(READY).initialise(() -> 0);
                        ctx.shared(DONE).initialise(() -> 0);
                        pc = 2;
                        continue;
                    case 2: if (!arrive(ctx, TEAM, me != 2, 3, 14)) return; continue;
                    case 3: if (!arrive(ctx, DEEP, me == 0, 4, 8)) return; continue;
                    case 4: ctx.shared(READY).getAndUpdate(n -> n + 1); if (!step(ctx, 5)) return; continue;
                    case 5: if (!busyWait(ctx, ctx.shared(DONE).get() == 0, 6)) return; continue;
                    case 6: self.nop(); if (!step(ctx, 7)) return; continue;
                    case 7: if (!leave(ctx, DEEP, 8)) return; continue;
                    case 8: if (!endOf(ctx, DEEP.sequence(), 9)) return; continue;
                    case 9: pc = me == 1 ? 10 : 13; continue;
                    case 10: if (!busyWait(ctx, ctx.shared(READY).get() < 2, 11)) return; continue;
                    case 11: ctx.emit(HELLO, "hi"); if (!step(ctx, 12)) return; continue;
                    case 12: ctx.shared(DONE).set(1); if (!step(ctx, 13)) return; continue;
                    case 13: if (!leave(ctx, TEAM, 14)) return; continue;
                    case 14: if (!endOf(ctx, TEAM.sequence(), 15)) return; continue;
                    case 15: pc = me == 2 ? 16 : 19; continue;
                    case 16: ctx.shared(READY).getAndUpdate(n -> n + 1); if (!step(ctx, 17)) return; continue;
                    case 17: if (!busyWait(ctx, ctx.shared(DONE).get() == 0, 18)) return; continue;
                    case 18: self.nop(); if (!step(ctx, 19)) return; continue;
                    case 19: if (!leave(ctx, MAIN, 20)) return; continue;
                    case 20: if (!endOf(ctx, MAIN.sequence(), 21)) return; continue;
                    case 21: ctx.finish(); return;
                    case 30:
                        self.logln(me + " heard " + ctx.messageOf(HELLO));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    case 31: self.logln(me + " outside heard"); if (!resumeAfterReaction(ctx)) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aSharedEventReachesExactlyTheMembersOfItsBlockIncludingNestedOnes(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = Missions.run(driver, SharedToNested.MAIN, 3, SharedToNested::new, trace).journal();
            assertEquals(List.of("0 heard hi", "1 heard hi"), ReactionRulesTest.sortedLines(journal));
            assertEquals(List.of(2), trace.events(TraceEvent.EventEmitted.class).stream()
                    .map(TraceEvent.EventEmitted::receivers).toList());
        }
    }

    /**
     * {@code K} emissions of a shared event by each of {@code N} agents at once, each agent
     * recording the messages it reacted to:
     * <pre>
     * asynchronous entry main (true) {
     *   shared event ping;
     *   shared int inside = 0, done = 0;
     *   local int i = 0;
     *   inside++;
     *   while (inside &lt; N) {}
     *   for (i = 0; i &lt; K; i++) emitWithMessage(ping, .getProxyID() + ":" + i);
     *   done++;
     *   while (done &lt; N) {}
     *   .nop();
     *   react (ping) { record(getMessageFromEvent(ping)); resume; }
     * }
     * </pre>
     */
    static final class ConcurrentEmission extends CompactProgram {
        static final int N = 8;
        static final int K = 50;
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event PING = MAIN.declareSharedEvent("ping");
        static final SharedDeclaration<Integer> INSIDE = MAIN.declareShared("inside", 0);
        static final SharedDeclaration<Integer> DONE = MAIN.declareShared("done", 0);
        static final Reaction MAIN_PING = MAIN.react(PING);

        final List<String> received = new ArrayList<>();
        private int i;

        ConcurrentEmission(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 20;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 9)) return; continue;
                    case 1:
                        ctx.shared(INSIDE).initialise(() -> 0);
                        ctx.shared(DONE).initialise(() -> 0);
                        i = 0;
                        ctx.shared(INSIDE).getAndUpdate(n -> n + 1);
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2: if (!busyWait(ctx, ctx.shared(INSIDE).get() < N, 3)) return; continue;
                    case 3:
                        if (!(i < K)) {
                            pc = 5;
                            continue;
                        }
                        ctx.emit(PING, self.getProxyID() + ":" + i);
                        if (!step(ctx, 4)) return;
                        continue;
                    case 4: i++; if (!loop(ctx, 3)) return; continue;
                    case 5: ctx.shared(DONE).getAndUpdate(n -> n + 1); if (!step(ctx, 6)) return; continue;
                    case 6: if (!busyWait(ctx, ctx.shared(DONE).get() < N, 7)) return; continue;
                    case 7: self.nop(); if (!step(ctx, 8)) return; continue;
                    case 8: if (!leave(ctx, MAIN, 9)) return; continue;
                    case 9: if (!endOf(ctx, MAIN.sequence(), 10)) return; continue;
                    case 10: ctx.finish(); return;
                    case 20: received.add(ctx.messageOf(PING)); if (!resumeAfterReaction(ctx)) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void concurrentEmittersLoseNothingAndEachEmittersOrderIsKept(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            List<ConcurrentEmission> programs = new ArrayList<>();
            Missions.run(driver, ConcurrentEmission.MAIN, ConcurrentEmission.N, self -> {
                ConcurrentEmission program = new ConcurrentEmission(self);
                synchronized (programs) {
                    programs.add(program);
                }
                return program;
            });
            for (ConcurrentEmission program : programs) {
                assertEquals(ConcurrentEmission.N * ConcurrentEmission.K, program.received.size());
                int[] next = new int[ConcurrentEmission.N];
                for (String message : program.received) {
                    String[] parts = message.split(":");
                    int emitter = Integer.parseInt(parts[0]);
                    assertEquals(next[emitter]++, Integer.parseInt(parts[1]), "order of emitter " + emitter);
                }
            }
        }
    }

    /** An agent type whose primitive throws for a zero divisor. */
    public static class Divider extends TestAgent {
        public int divide(int dividend, int divisor) {
            return dividend / divisor;
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local int q = 7;
     *   q = .divide(1, 0);
     *   .logln("q=" + q);
     *   react (uncaught_exception) { .logln("caught " + getMessageFromEvent(uncaught_exception)); resume; }
     * }
     * </pre>
     */
    static final class Uncaught extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Reaction MAIN_UNCAUGHT = MAIN.react(Event.UNCAUGHT_EXCEPTION);

        private final Divider divider;
        private int q;

        Uncaught(Divider self) {
            super(self);
            this.divider = self;
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 20;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 4)) return; continue;
                    case 1:
                        q = 7;
                        try {
                            q = divider.divide(1, 0);
                        } catch (RuntimeException thrown) {
                            ctx.uncaughtException(thrown);
                            q = 0;
                        }
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2: self.logln("q=" + q); if (!step(ctx, 3)) return; continue;
                    case 3: if (!leave(ctx, MAIN, 4)) return; continue;
                    case 4: if (!endOf(ctx, MAIN.sequence(), 5)) return; continue;
                    case 5: ctx.finish(); return;
                    case 20:
                        self.logln("caught " + ctx.messageOf(Event.UNCAUGHT_EXCEPTION));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anExceptionOfAPrimitiveBecomesUncaughtExceptionAndTheMissionGoesOn(Driver driver) throws InterruptedException {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MissionOutcome outcome = Mission.builder().main(Uncaught.MAIN).scheduler(driver.newScheduler())
                    .agent("a", new Divider(), Uncaught::new)
                    .agent("b", new Divider(), Uncaught::new)
                    .build().run(Duration.ofSeconds(20)).requireCompleted();
            assertEquals(List.of("caught java.lang.ArithmeticException", "caught java.lang.ArithmeticException",
                    "q=0", "q=0"), ReactionRulesTest.sortedLines(outcome.journal()));
        }
    }

    /**
     * Workers loop until the boss aborts them:
     * <pre>
     * asynchronous entry main (true) {
     *   shared event abort;
     *   shared int working = 0;
     *   asynchronous entry work (.getProxyID() != 0) {
     *     working++;
     *     while (true) { .nop(); }
     *     react (abort) { .logln("worker " + .getProxyID() + " stops"); break; }
     *   }
     *   asynchronous entry boss (.getProxyID() == 0) {
     *     while (working &lt; 3) {}
     *     emit(abort);
     *   }
     *   .logln("left " + .getProxyID());
     * }
     * </pre>
     */
    static final class Abort extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event ABORT = MAIN.declareSharedEvent("abort");
        static final SharedDeclaration<Integer> WORKING = MAIN.declareShared("working", 0);
        static final ESequence WORK_BOSS = MAIN.newSequence();
        static final EntryDefinition WORK = WORK_BOSS.block("work", Mode.ASYNCHRONOUS);
        static final EntryDefinition BOSS = WORK_BOSS.block("boss", Mode.ASYNCHRONOUS);
        static final Reaction WORK_ABORT = WORK.react(ABORT);

        Abort(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 20;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 14)) return; continue;
                    case 1: ctx.shared(WORKING).initialise(() -> 0); pc = 2; continue;
                    case 2: if (!arrive(ctx, WORK, self.getProxyID() != 0, 3, 7)) return; continue;
                    case 3: ctx.shared(WORKING).getAndUpdate(n -> n + 1); if (!step(ctx, 4)) return; continue;
                    case 4: self.nop(); if (!step(ctx, 5)) return; continue;
                    case 5: if (!loop(ctx, 4)) return; continue;
                    case 6: if (!leave(ctx, WORK, 7)) return; continue;
                    case 7: if (!arrive(ctx, BOSS, self.getProxyID() == 0, 8, 11)) return; continue;
                    case 8: if (!busyWait(ctx, ctx.shared(WORKING).get() < 3, 9)) return; continue;
                    case 9: ctx.emit(ABORT); if (!step(ctx, 10)) return; continue;
                    case 10: if (!leave(ctx, BOSS, 11)) return; continue;
                    case 11: if (!endOf(ctx, WORK_BOSS, 12)) return; continue;
                    case 12: self.logln("left " + self.getProxyID()); if (!step(ctx, 13)) return; continue;
                    case 13: if (!leave(ctx, MAIN, 14)) return; continue;
                    case 14: if (!endOf(ctx, MAIN.sequence(), 15)) return; continue;
                    case 15: ctx.finish(); return;
                    case 20:
                        self.logln("worker " + self.getProxyID() + " stops");
                        if (!breakAfterReaction(ctx, WORK, 7)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aTeamAbortsInterruptibleWorkWithAnEvent(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            String journal = Missions.run(driver, Abort.MAIN, 4, Abort::new).journal();
            assertEquals(List.of("left 0", "left 1", "left 2", "left 3",
                    "worker 1 stops", "worker 2 stops", "worker 3 stops"), ReactionRulesTest.sortedLines(journal));
            for (int worker = 1; worker <= 3; worker++) {
                assertTrue(journal.indexOf("worker " + worker + " stops") < journal.indexOf("left " + worker), journal);
            }
        }
    }

    /**
     * Lock-step with an event: agent 0 emits at the second instruction; everyone reacts at that
     * instruction's boundary or, if it had passed its event step before the emission and was
     * waiting at the barrier, at the next one; the block stays in lock-step.
     * <pre>
     * synchronous entry main (true) {
     *   shared event tick;
     *   .nop();                                               // i1
     *   if (.getProxyID() == 0) emit(tick); else .nop();      // i2
     *   .nop();                                               // i3
     *   .nop();                                               // i4
     *   react (tick) { .logln("tick"); resume; }
     * }
     * </pre>
     */
    static final class LockStepTick extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final Event TICK = MAIN.declareSharedEvent("tick");
        static final Reaction MAIN_TICK = MAIN.react(TICK);

        private final PhaseLog log;
        private final PhaseLog ticks;

        LockStepTick(TestAgent self, PhaseLog log, PhaseLog ticks) {
            super(self);
            this.log = log;
            this.ticks = ticks;
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 20;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 6)) return; continue;
                    case 1: log.instruction(me, "i1"); if (!step(ctx, 2)) return; continue;
                    case 2:
                        log.instruction(me, "i2");
                        if (me == 0) {
                            ctx.emit(TICK);
                        }
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3: log.instruction(me, "i3"); if (!step(ctx, 4)) return; continue;
                    case 4: log.instruction(me, "i4"); if (!step(ctx, 5)) return; continue;
                    case 5: if (!leave(ctx, MAIN, 6)) return; continue;
                    case 6: if (!endOf(ctx, MAIN.sequence(), 7)) return; continue;
                    case 7: ctx.finish(); return;
                    case 20:
                        ticks.instruction(me, "tick");
                        self.logln("tick");
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void reactionsInLockStepHappenAtTheEmissionsBoundaryOrTheNextOne(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            // A reaction is not an instruction: it shares its phase with the instruction before it,
            // so reactions are logged apart, against the same barrier trips.
            PhaseLog ticks = new PhaseLog("main", Trace.NONE);
            PhaseLog instructions = new PhaseLog("main", ticks);
            String journal = Missions.run(driver, LockStepTick.MAIN, 3,
                    self -> new LockStepTick(self, instructions, ticks), instructions).journal();
            assertEquals("tick\ntick\ntick\n", journal);
            assertEquals(List.of(), instructions.lockStepViolations());
            for (int agent = 0; agent < 3; agent++) {
                Map<String, Integer> mine = instructions.phases().get(agent);
                assertEquals(List.of(0, 1, 2, 3),
                        List.of(mine.get("i1"), mine.get("i2"), mine.get("i3"), mine.get("i4")));
                int tick = ticks.phases().get(agent).get("tick");
                assertTrue(tick == 1 || tick == 2, "agent " + agent + " reacted in phase " + tick);
            }
            assertEquals(1, ticks.phases().get(0).get("tick"), "the emitter reacts at its own boundary");
        }
    }

    /**
     * After the emission nothing changes that a busy-wait could see but the event itself: the
     * listener, parked in {@code while (!heard) {}}, must be woken by perceiving it.
     * <pre>
     * asynchronous entry main (true) {
     *   shared event go;
     *   shared int listening = 0, acknowledged = 0;
     *   local boolean heard = false;
     *   asynchronous entry talk (.getProxyID() == 0) {
     *     while (listening == 0) {}
     *     emit(go);
     *     while (acknowledged == 0) {}
     *   }
     *   asynchronous entry listen (.getProxyID() == 1) {
     *     listening = 1;
     *     while (!heard) {}
     *     acknowledged = 1;
     *     react (go) { heard = true; resume; }
     *   }
     * }
     * </pre>
     */
    static final class WakeUp extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event GO = MAIN.declareSharedEvent("go");
        static final SharedDeclaration<Integer> LISTENING = MAIN.declareShared("listening", 0);
        static final SharedDeclaration<Integer> ACKNOWLEDGED = MAIN.declareShared("acknowledged", 0);
        static final ESequence TALK_LISTEN = MAIN.newSequence();
        static final EntryDefinition TALK = TALK_LISTEN.block("talk", Mode.ASYNCHRONOUS);
        static final EntryDefinition LISTEN = TALK_LISTEN.block("listen", Mode.ASYNCHRONOUS);
        static final Reaction LISTEN_GO = LISTEN.react(GO);

        private boolean heard;

        WakeUp(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 20;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 14)) return; continue;
                    case 1:
                        ctx.shared(LISTENING).initialise(() -> 0);
                        ctx.shared(ACKNOWLEDGED).initialise(() -> 0);
                        heard = false;
                        pc = 2;
                        continue;
                    case 2: if (!arrive(ctx, TALK, self.getProxyID() == 0, 3, 7)) return; continue;
                    case 3: if (!busyWait(ctx, ctx.shared(LISTENING).get() == 0, 4)) return; continue;
                    case 4: ctx.emit(GO); if (!step(ctx, 5)) return; continue;
                    case 5: if (!busyWait(ctx, ctx.shared(ACKNOWLEDGED).get() == 0, 6)) return; continue;
                    case 6: if (!leave(ctx, TALK, 7)) return; continue;
                    case 7: if (!arrive(ctx, LISTEN, self.getProxyID() == 1, 8, 12)) return; continue;
                    case 8: ctx.shared(LISTENING).set(1); if (!step(ctx, 9)) return; continue;
                    case 9: if (!busyWait(ctx, !heard, 10)) return; continue;
                    case 10: ctx.shared(ACKNOWLEDGED).set(1); if (!step(ctx, 11)) return; continue;
                    case 11: if (!leave(ctx, LISTEN, 12)) return; continue;
                    case 12: if (!endOf(ctx, TALK_LISTEN, 13)) return; continue;
                    case 13: if (!leave(ctx, MAIN, 14)) return; continue;
                    case 14: if (!endOf(ctx, MAIN.sequence(), 15)) return; continue;
                    case 15: ctx.finish(); return;
                    case 20: heard = true; if (!resumeAfterReaction(ctx)) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anEventWakesAnAgentParkedInABusyWait(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            Missions.run(driver, WakeUp.MAIN, 2, WakeUp::new, trace);
            assertEquals(List.of("go@listen"), ReactionRulesTest.reactions(trace));
        }
    }

    /**
     * A reaction's {@code break} out of a synchronous child: the leavers are no longer waited for.
     * <pre>
     * synchronous entry main (true) {
     *   synchronous entry work (true) {
     *     shared event stop;
     *     .log("w1 ");
     *     if (.getProxyID() == 0) emit(stop); else .nop();
     *     .log("w3 ");
     *     .log("w4 ");
     *     react (stop) { break; }
     *   }
     *   .logln("after");
     * }
     * </pre>
     * Every member reacts at the boundary of the emission or of {@code w3}: nobody logs {@code w4}.
     */
    static final class BreakInLockStep extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        static final EntryDefinition WORK = MAIN.child("work", Mode.SYNCHRONOUS);
        static final Event STOP = WORK.declareSharedEvent("stop");
        static final Reaction WORK_STOP = WORK.react(STOP);

        BreakInLockStep(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 20;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 10)) return; continue;
                    case 1: if (!arrive(ctx, WORK, true, 2, 7)) return; continue;
                    case 2: self.log("w1 "); if (!step(ctx, 3)) return; continue;
                    case 3:
                        if (self.getProxyID() == 0) {
                            ctx.emit(STOP);
                        } else {
                            self.nop();
                        }
                        if (!step(ctx, 4)) return;
                        continue;
                    case 4: self.log("w3 "); if (!step(ctx, 5)) return; continue;
                    case 5: self.log("w4 "); if (!step(ctx, 6)) return; continue;
                    case 6: if (!leave(ctx, WORK, 7)) return; continue;
                    case 7: if (!endOf(ctx, WORK.sequence(), 8)) return; continue;
                    case 8: self.logln("after"); if (!step(ctx, 9)) return; continue;
                    case 9: if (!leave(ctx, MAIN, 10)) return; continue;
                    case 10: if (!endOf(ctx, MAIN.sequence(), 11)) return; continue;
                    case 11: ctx.finish(); return;
                    case 20: if (!breakAfterReaction(ctx, WORK, 7)) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aReactionsBreakOutOfASynchronousBlockIsNotWaitedFor(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = Missions.run(driver, BreakInLockStep.MAIN, 3, BreakInLockStep::new, trace).journal();
            assertEquals(3, journal.split("w1 ", -1).length - 1, journal);
            assertEquals(3, journal.split("after\n", -1).length - 1, journal);
            assertTrue(!journal.contains("w4"), journal);
            assertEquals(3, trace.events(TraceEvent.Left.class).stream()
                    .filter(e -> e.block().equals("work") && e.cause() == LeaveCause.BREAK).count());
        }
    }

    /**
     * Agent 1 is held by the free entry barrier of {@code gate} (agent 0, in the same wave of
     * {@code main}, has not reached its e-sequence yet) when agent 0 emits: as a member of
     * {@code main} it perceives the event, but is not woken for it; it reacts at its first boundary
     * once let in.
     * <pre>
     * asynchronous entry main (true) {
     *   shared event open;
     *   shared int inside = 0;
     *   inside++;
     *   while (inside &lt; 2) {}
     *   asynchronous entry talk (.getProxyID() == 0) {
     *     while (gate.getWaitingInCount() == 0) {}
     *     emitWithMessage(open, "now");
     *   }
     *   .nop();
     *   synchronous entry gate (.getProxyID() == 1) {
     *     .logln("in gate");
     *   }
     *   react (open) { .logln(.getProxyID() + " heard " + getMessageFromEvent(open)); resume; }
     * }
     * </pre>
     */
    static final class HeldMember extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event OPEN = MAIN.declareSharedEvent("open");
        static final SharedDeclaration<Integer> INSIDE = MAIN.declareShared("inside", 0);
        static final EntryDefinition TALK = MAIN.child("talk", Mode.ASYNCHRONOUS);
        static final EntryDefinition GATE = MAIN.child("gate", Mode.SYNCHRONOUS);
        static final Reaction MAIN_OPEN = MAIN.react(OPEN);

        HeldMember(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 20;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 14)) return; continue;
                    case 1:
                        ctx.shared(INSIDE).initialise(() -> 0);
                        ctx.shared(INSIDE).getAndUpdate(n -> n + 1);
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2: if (!busyWait(ctx, ctx.shared(INSIDE).get() < 2, 3)) return; continue;
                    case 3: if (!arrive(ctx, TALK, me == 0, 4, 7)) return; continue;
                    case 4: if (!busyWait(ctx, ctx.entry(GATE).getWaitingInCount() == 0, 5)) return; continue;
                    case 5: ctx.emit(OPEN, "now"); if (!step(ctx, 6)) return; continue;
                    case 6: if (!leave(ctx, TALK, 7)) return; continue;
                    case 7: if (!endOf(ctx, TALK.sequence(), 8)) return; continue;
                    case 8: self.nop(); if (!step(ctx, 9)) return; continue;
                    case 9: if (!arrive(ctx, GATE, me == 1, 10, 12)) return; continue;
                    case 10: self.logln("in gate"); if (!step(ctx, 11)) return; continue;
                    case 11: if (!leave(ctx, GATE, 12)) return; continue;
                    case 12: if (!endOf(ctx, GATE.sequence(), 13)) return; continue;
                    case 13: if (!leave(ctx, MAIN, 14)) return; continue;
                    case 14: if (!endOf(ctx, MAIN.sequence(), 15)) return; continue;
                    case 15: ctx.finish(); return;
                    case 20:
                        self.logln(me + " heard " + ctx.messageOf(OPEN));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anAgentHeldByAnEntryBarrierPerceivesButReactsOnlyOnceLetIn(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = Missions.run(driver, HeldMember.MAIN, 2, HeldMember::new, trace).journal();
            assertEquals(List.of("0 heard now", "1 heard now", "in gate"), ReactionRulesTest.sortedLines(journal));
            assertTrue(journal.indexOf("in gate") < journal.indexOf("1 heard now"), journal);
            assertEquals(List.of(2), trace.events(TraceEvent.EventEmitted.class).stream()
                    .map(TraceEvent.EventEmitted::receivers).toList());
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   asynchronous entry team (false) { shared event hello; }
     *   emit(hello);             // a compile error in MASL: the runtime refuses it
     * }
     * </pre>
     */
    @Test
    void emittingOutsideTheDeclaringBlockFailsTheMission() throws InterruptedException {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        EntryDefinition team = main.child("team", Mode.ASYNCHRONOUS);
        Event hello = team.declareSharedEvent("hello");
        MissionOutcome outcome = Mission.builder().main(main)
                .agent("a", new TestAgent(), self -> new CompactProgram(self) {
                    @Override
                    protected void resume(AgentContext ctx) {
                        while (true) {
                            switch (pc) {
                                case 0: if (!arrive(ctx, main, true, 1, 9)) return; continue;
                                case 1: if (!arrive(ctx, team, false, 2, 3)) return; continue;
                                case 3: if (!endOf(ctx, team.sequence(), 4)) return; continue;
                                case 4: ctx.emit(hello); if (!step(ctx, 5)) return; continue;
                                default: throw new IllegalStateException("pc " + pc);
                            }
                        }
                    }
                })
                .build().run(Duration.ofSeconds(20));
        assertEquals(MissionOutcome.Status.FAILED, outcome.status());
        assertTrue(outcome.failure().orElseThrow().getCause().getMessage()
                .contains("emits shared event hello of team outside that block"), outcome.failure().toString());
    }
}
