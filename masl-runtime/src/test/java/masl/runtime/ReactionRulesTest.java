package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The rules of MASL §8 for one agent's processing, each on a small program written in the
 * generated-code contract: priority, the last reaction deciding, lookup in the enclosing blocks,
 * {@code react(default)}, occurrences perceived during processing, {@code clearEvents}, dropping.
 */
@Timeout(120)
class ReactionRulesTest {

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local event x, y, z, go;
     *   asynchronous entry inner (true) {
     *     emit(go);
     *     .logln("end");
     *     react (z) { .logln("z"); resume; }
     *     react (y) { .logln("y"); resume; }
     *   }
     *   react (x) { .logln("x"); resume; }
     *   react (go) { emit(x); emit(y); emit(z); resume; }
     * }
     * </pre>
     */
    static final class Priority extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event X = MAIN.declareLocalEvent("x");
        static final Event Y = MAIN.declareLocalEvent("y");
        static final Event Z = MAIN.declareLocalEvent("z");
        static final Event GO = MAIN.declareLocalEvent("go");
        static final EntryDefinition INNER = MAIN.child("inner", Mode.ASYNCHRONOUS);
        static final Reaction INNER_Z = INNER.react(Z);
        static final Reaction INNER_Y = INNER.react(Y);
        static final Reaction MAIN_X = MAIN.react(X);
        static final Reaction MAIN_GO = MAIN.react(GO);

        Priority(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == INNER_Z ? 10 : reaction == INNER_Y ? 11 : reaction == MAIN_X ? 12 : 13;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 7)) return; continue;
                    case 1: if (!arrive(ctx, INNER, true, 2, 5)) return; continue;
                    case 2: ctx.emit(GO); if (!step(ctx, 3)) return; continue;
                    case 3: self.logln("end"); if (!step(ctx, 4)) return; continue;
                    case 4: if (!leave(ctx, INNER, 5)) return; continue;
                    case 5: if (!endOf(ctx, INNER.sequence(), 6)) return; continue;
                    case 6: if (!leave(ctx, MAIN, 7)) return; continue;
                    case 7: if (!endOf(ctx, MAIN.sequence(), 8)) return; continue;
                    case 8: ctx.finish(); return;
                    case 10: self.logln("z"); if (!resumeAfterReaction(ctx)) return; continue;
                    case 11: self.logln("y"); if (!resumeAfterReaction(ctx)) return; continue;
                    case 12: self.logln("x"); if (!resumeAfterReaction(ctx)) return; continue;
                    case 13:
                        ctx.emit(X);
                        ctx.emit(Y);
                        ctx.emit(Z);
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void innermostBlockFirstThenReactionsInTheOrderWritten(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            // x, y, z were perceived in this order; inner's reactions come first, z before y as written.
            assertEquals("end\nz\ny\nx\n", Missions.run(driver, Priority.MAIN, 1, Priority::new, trace).journal());
            assertEquals(List.of("go@main", "z@inner", "y@inner", "x@main"), reactions(trace));
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local event ping;
     *   local int n = 0;
     *   emit(ping);
     *   .logln("1");
     *   .logln("2");
     *   .logln("3");
     *   react (ping) { n++; .logln("ping " + n); if (n &lt; 3) emit(ping); resume; }
     * }
     * </pre>
     */
    static final class NextBoundary extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event PING = MAIN.declareLocalEvent("ping");
        static final Reaction MAIN_PING = MAIN.react(PING);

        private int n;

        NextBoundary(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return 10;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 6)) return; continue;
                    case 1: n = 0; ctx.emit(PING); if (!step(ctx, 2)) return; continue;
                    case 2: self.logln("1"); if (!step(ctx, 3)) return; continue;
                    case 3: self.logln("2"); if (!step(ctx, 4)) return; continue;
                    case 4: self.logln("3"); if (!step(ctx, 5)) return; continue;
                    case 5: if (!leave(ctx, MAIN, 6)) return; continue;
                    case 6: if (!endOf(ctx, MAIN.sequence(), 7)) return; continue;
                    case 7: ctx.finish(); return;
                    case 10:
                        n++;
                        self.logln("ping " + n);
                        if (n < 3) {
                            ctx.emit(PING);
                        }
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anOccurrencePerceivedDuringProcessingWaitsForTheNextBoundary(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("ping 1\n1\nping 2\n2\nping 3\n3\n",
                    Missions.run(driver, NextBoundary.MAIN, 1, NextBoundary::new).journal());
        }
    }

    /**
     * Two reactions of {@code work} to occurrences queued together; which one is written first is
     * the variant:
     * <pre>
     * asynchronous entry main (true) {
     *   local event go, leave, stay;
     *   asynchronous entry work (true) {
     *     emit(go);
     *     .logln("stayed");
     *     .logln("resumed");
     *     react (leave) { .logln("leave"); break; }      // first if leaveFirst
     *     react (stay) { .logln("stay"); resume; }
     *   }
     *   .logln("after work");
     *   react (go) { emit(stay); emit(leave); resume; }
     * }
     * </pre>
     */
    static final class LastDecides extends CompactProgram {
        static final class Blocks {
            final EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
            final Event go = main.declareLocalEvent("go");
            final Event leave = main.declareLocalEvent("leave");
            final Event stay = main.declareLocalEvent("stay");
            final EntryDefinition work = main.child("work", Mode.ASYNCHRONOUS);
            final Reaction workLeave;
            final Reaction workStay;
            final Reaction mainGo = main.react(go);

            Blocks(boolean leaveFirst) {
                if (leaveFirst) {
                    workLeave = work.react(leave);
                    workStay = work.react(stay);
                } else {
                    workStay = work.react(stay);
                    workLeave = work.react(leave);
                }
            }
        }

        static final Blocks LEAVE_FIRST = new Blocks(true);
        static final Blocks STAY_FIRST = new Blocks(false);

        private final Blocks b;

        LastDecides(TestAgent self, Blocks blocks) {
            super(self);
            this.b = blocks;
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == b.workLeave ? 20 : reaction == b.workStay ? 21 : 22;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, b.main, true, 1, 9)) return; continue;
                    case 1: if (!arrive(ctx, b.work, true, 2, 6)) return; continue;
                    case 2: ctx.emit(b.go); if (!step(ctx, 3)) return; continue;
                    case 3: self.logln("stayed"); if (!step(ctx, 4)) return; continue;
                    case 4: self.logln("resumed"); if (!step(ctx, 5)) return; continue;
                    case 5: if (!leave(ctx, b.work, 6)) return; continue;
                    case 6: if (!endOf(ctx, b.work.sequence(), 7)) return; continue;
                    case 7: self.logln("after work"); if (!step(ctx, 8)) return; continue;
                    case 8: if (!leave(ctx, b.main, 9)) return; continue;
                    case 9: if (!endOf(ctx, b.main.sequence(), 10)) return; continue;
                    case 10: ctx.finish(); return;
                    case 20: self.logln("leave"); if (!breakAfterReaction(ctx, b.work, 6)) return; continue;
                    case 21: self.logln("stay"); if (!resumeAfterReaction(ctx)) return; continue;
                    case 22:
                        ctx.emit(b.stay);
                        ctx.emit(b.leave);
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void theLastReactionRunDecides(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("stayed\nleave\nstay\nresumed\nafter work\n", Missions.run(driver,
                    LastDecides.LEAVE_FIRST.main, 1, self -> new LastDecides(self, LastDecides.LEAVE_FIRST)).journal());
            assertEquals("stayed\nstay\nleave\nafter work\n", Missions.run(driver,
                    LastDecides.STAY_FIRST.main, 1, self -> new LastDecides(self, LastDecides.STAY_FIRST)).journal());
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local event alarm;
     *   asynchronous entry top (true) {
     *     asynchronous entry mid (true) {
     *       asynchronous entry inner (true) {
     *         emit(alarm);
     *         .logln("never");
     *       }
     *       .logln("never");
     *     }
     *     .logln("never");
     *     react (alarm) { .logln("top reacts"); break; }
     *   }
     *   .logln("after top");
     * }
     * </pre>
     */
    static final class GrandParent extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event ALARM = MAIN.declareLocalEvent("alarm");
        static final EntryDefinition TOP = MAIN.child("top", Mode.ASYNCHRONOUS);
        static final EntryDefinition MID = TOP.child("mid", Mode.ASYNCHRONOUS);
        static final EntryDefinition INNER = MID.child("inner", Mode.ASYNCHRONOUS);
        static final Reaction TOP_ALARM = TOP.react(ALARM);

        GrandParent(TestAgent self) {
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
                    case 0: if (!arrive(ctx, MAIN, true, 1, 16)) return; continue;
                    case 1: if (!arrive(ctx, TOP, true, 2, 13)) return; continue;
                    case 2: if (!arrive(ctx, MID, true, 3, 10)) return; continue;
                    case 3: if (!arrive(ctx, INNER, true, 4, 7)) return; continue;
                    case 4: ctx.emit(ALARM); if (!step(ctx, 5)) return; continue;
                    case 5: self.logln("never"); if (!step(ctx, 6)) return; continue;
                    case 6: if (!leave(ctx, INNER, 7)) return; continue;
                    case 7: if (!endOf(ctx, INNER.sequence(), 8)) return; continue;
                    case 8: self.logln("never"); if (!step(ctx, 9)) return; continue;
                    case 9: if (!leave(ctx, MID, 10)) return; continue;
                    case 10: if (!endOf(ctx, MID.sequence(), 11)) return; continue;
                    case 11: self.logln("never"); if (!step(ctx, 12)) return; continue;
                    case 12: if (!leave(ctx, TOP, 13)) return; continue;
                    case 13: if (!endOf(ctx, TOP.sequence(), 14)) return; continue;
                    case 14: self.logln("after top"); if (!step(ctx, 15)) return; continue;
                    case 15: if (!leave(ctx, MAIN, 16)) return; continue;
                    case 16: if (!endOf(ctx, MAIN.sequence(), 17)) return; continue;
                    case 17: ctx.finish(); return;
                    case 20: self.logln("top reacts"); if (!breakAfterReaction(ctx, TOP, 13)) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aReactionFoundInTheGrandParentLeavesTheGrandParent(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = Missions.run(driver, GrandParent.MAIN, 2, GrandParent::new, trace).journal();
            assertEquals(List.of("after top", "after top", "top reacts", "top reacts"), sortedLines(journal));
            for (int agent = 0; agent < 2; agent++) {
                int id = agent;
                assertEquals(List.of("inner:BREAK", "mid:BREAK", "top:BREAK", "main:END"),
                        trace.events(TraceEvent.Left.class).stream().filter(e -> e.agent() == id)
                                .map(e -> e.block() + ":" + e.cause()).toList());
            }
            assertEquals(List.of("alarm@top", "alarm@top"), reactions(trace));
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local event a, b;
     *   asynchronous entry work (true) {
     *     emitWithMessage(a, "ma");
     *     emitWithMessage(b, "mb");
     *     .logln("end");
     *     react (a) { .logln("a " + getMessageFromEvent(a)); resume; }
     *     react (default) { .logln("default " + getMessageFromEvent(a) + " " + getMessageFromEvent(b)); resume; }
     *   }
     *   react (b) { .logln("main b"); resume; }
     * }
     * </pre>
     */
    static final class Default extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event A = MAIN.declareLocalEvent("a");
        static final Event B = MAIN.declareLocalEvent("b");
        static final EntryDefinition WORK = MAIN.child("work", Mode.ASYNCHRONOUS);
        static final Reaction WORK_A = WORK.react(A);
        static final Reaction WORK_DEFAULT = WORK.reactToDefault();
        static final Reaction MAIN_B = MAIN.react(B);

        Default(TestAgent self) {
            super(self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == WORK_A ? 20 : reaction == WORK_DEFAULT ? 21 : 22;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 8)) return; continue;
                    case 1: if (!arrive(ctx, WORK, true, 2, 6)) return; continue;
                    case 2: ctx.emit(A, "ma"); if (!step(ctx, 3)) return; continue;
                    case 3: ctx.emit(B, "mb"); if (!step(ctx, 4)) return; continue;
                    case 4: self.logln("end"); if (!step(ctx, 5)) return; continue;
                    case 5: if (!leave(ctx, WORK, 6)) return; continue;
                    case 6: if (!endOf(ctx, WORK.sequence(), 7)) return; continue;
                    case 7: if (!leave(ctx, MAIN, 8)) return; continue;
                    case 8: if (!endOf(ctx, MAIN.sequence(), 9)) return; continue;
                    case 9: ctx.finish(); return;
                    case 20: self.logln("a " + ctx.messageOf(A)); if (!resumeAfterReaction(ctx)) return; continue;
                    case 21:
                        self.logln("default " + ctx.messageOf(A) + " " + ctx.messageOf(B));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    case 22: self.logln("main b"); if (!resumeAfterReaction(ctx)) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aBlocksDefaultReactionComesBeforeTheParentsReaction(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            // getMessageFromEvent(a) while reacting to b: no occurrence of a is being handled.
            assertEquals("a ma\ndefault null mb\nend\n", Missions.run(driver, Default.MAIN, 1, Default::new).journal());
        }
    }

    /**
     * {@code clears} chooses whether {@code react(a)} calls {@code clearEvents}:
     * <pre>
     * asynchronous entry main (true) {
     *   local event go, a, b, c;
     *   emit(go);
     *   .logln("x");
     *   .logln("y");
     *   react (a) { .logln("a"); clearEvents; resume; }
     *   react (b) { .logln("b"); break; }
     *   react (c) { .logln("c"); break; }
     *   react (go) { emit(c); emit(b); emit(a); resume; }
     * }
     * </pre>
     */
    static final class Clear extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event GO = MAIN.declareLocalEvent("go");
        static final Event A = MAIN.declareLocalEvent("a");
        static final Event B = MAIN.declareLocalEvent("b");
        static final Event C = MAIN.declareLocalEvent("c");
        static final Reaction MAIN_A = MAIN.react(A);
        static final Reaction MAIN_B = MAIN.react(B);
        static final Reaction MAIN_C = MAIN.react(C);
        static final Reaction MAIN_GO = MAIN.react(GO);

        private final boolean clears;

        Clear(TestAgent self, boolean clears) {
            super(self);
            this.clears = clears;
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == MAIN_A ? 20 : reaction == MAIN_B ? 21 : reaction == MAIN_C ? 22 : 23;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 5)) return; continue;
                    case 1: ctx.emit(GO); if (!step(ctx, 2)) return; continue;
                    case 2: self.logln("x"); if (!step(ctx, 3)) return; continue;
                    case 3: self.logln("y"); if (!step(ctx, 4)) return; continue;
                    case 4: if (!leave(ctx, MAIN, 5)) return; continue;
                    case 5: if (!endOf(ctx, MAIN.sequence(), 6)) return; continue;
                    case 6: ctx.finish(); return;
                    case 20:
                        self.logln("a");
                        if (clears) {
                            ctx.clearEvents();
                        }
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    case 21: self.logln("b"); if (!breakAfterReaction(ctx, MAIN, 5)) return; continue;
                    case 22: self.logln("c"); if (!breakAfterReaction(ctx, MAIN, 5)) return; continue;
                    case 23:
                        ctx.emit(C);
                        ctx.emit(B);
                        ctx.emit(A);
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void clearEventsDropsTheRestSoThatTheCurrentReactionDecides(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("x\na\ny\n",
                    Missions.run(driver, Clear.MAIN, 1, self -> new Clear(self, true), trace).journal());
            assertEquals(List.of("b", "c"), trace.events(TraceEvent.EventDropped.class).stream()
                    .map(TraceEvent.EventDropped::event).toList());
            // Without clearEvents, c runs last and its break leaves main before "y".
            assertEquals("x\na\nb\nc\n", Missions.run(driver, Clear.MAIN, 1, self -> new Clear(self, false)).journal());
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local event lost, e;
     *   asynchronous entry work (true) {
     *     emit(lost);
     *     .logln("on");
     *     emit(e);
     *     .logln("never");
     *     react (e) { .logln("reacted"); }
     *   }
     *   .logln("after work");
     * }
     * </pre>
     */
    static final class DropAndLeave extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event LOST = MAIN.declareLocalEvent("lost");
        static final Event E = MAIN.declareLocalEvent("e");
        static final EntryDefinition WORK = MAIN.child("work", Mode.ASYNCHRONOUS);
        static final Reaction WORK_E = WORK.react(E);

        DropAndLeave(TestAgent self) {
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
                    case 2: ctx.emit(LOST); if (!step(ctx, 3)) return; continue;
                    case 3: self.logln("on"); if (!step(ctx, 4)) return; continue;
                    case 4: ctx.emit(E); if (!step(ctx, 5)) return; continue;
                    case 5: self.logln("never"); if (!step(ctx, 6)) return; continue;
                    case 6: if (!leave(ctx, WORK, 7)) return; continue;
                    case 7: if (!endOf(ctx, WORK.sequence(), 8)) return; continue;
                    case 8: self.logln("after work"); if (!step(ctx, 9)) return; continue;
                    case 9: if (!leave(ctx, MAIN, 10)) return; continue;
                    case 10: if (!endOf(ctx, MAIN.sequence(), 11)) return; continue;
                    case 11: ctx.finish(); return;
                    // 7: react (e) { .logln("reacted"); }  no ending statement: leaves work, as break would
                    case 20: self.logln("reacted"); if (!breakAfterReaction(ctx, WORK, 7)) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void unhandledOccurrencesAreDroppedAndAReactionWithoutEndingLeavesItsBlock(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("on\nreacted\nafter work\n",
                    Missions.run(driver, DropAndLeave.MAIN, 1, DropAndLeave::new, trace).journal());
            assertEquals(List.of("lost"), trace.events(TraceEvent.EventDropped.class).stream()
                    .map(TraceEvent.EventDropped::event).toList());
            assertEquals(List.of("e@work"), reactions(trace));
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local event again;
     *   local int k = 0;
     *   asynchronous entry outer (true) {
     *     .logln("outer " + k);
     *     asynchronous entry inner (true) {
     *       k++;
     *       emit(again);
     *       .logln("never");
     *     }
     *     .logln("never");
     *     react (again) { if (k &lt; 3) restart; else break; }
     *   }
     *   .logln("done " + k);
     * }
     * </pre>
     */
    static final class RestartFromReaction extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event AGAIN = MAIN.declareLocalEvent("again");
        static final EntryDefinition OUTER = MAIN.child("outer", Mode.ASYNCHRONOUS);
        static final EntryDefinition INNER = OUTER.child("inner", Mode.ASYNCHRONOUS);
        static final Reaction OUTER_AGAIN = OUTER.react(AGAIN);

        private int k;

        RestartFromReaction(TestAgent self) {
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
                    case 0: if (!arrive(ctx, MAIN, true, 1, 15)) return; continue;
                    case 1: k = 0; pc = 2; continue;
                    case 2: if (!arrive(ctx, OUTER, true, 3, 12)) return; continue;
                    case 3: self.logln("outer " + k); if (!step(ctx, 4)) return; continue;
                    case 4: if (!arrive(ctx, INNER, true, 5, 9)) return; continue;
                    case 5: k++; if (!step(ctx, 6)) return; continue;
                    case 6: ctx.emit(AGAIN); if (!step(ctx, 7)) return; continue;
                    case 7: self.logln("never"); if (!step(ctx, 8)) return; continue;
                    case 8: if (!leave(ctx, INNER, 9)) return; continue;
                    case 9: if (!endOf(ctx, INNER.sequence(), 10)) return; continue;
                    case 10: self.logln("never"); if (!step(ctx, 11)) return; continue;
                    case 11: if (!leave(ctx, OUTER, 12)) return; continue;
                    case 12: if (!endOf(ctx, OUTER.sequence(), 13)) return; continue;
                    case 13: self.logln("done " + k); if (!step(ctx, 14)) return; continue;
                    case 14: if (!leave(ctx, MAIN, 15)) return; continue;
                    case 15: if (!endOf(ctx, MAIN.sequence(), 16)) return; continue;
                    case 16: ctx.finish(); return;
                    case 20:
                        if (k < 3) {
                            if (!ctx.endReaction()) return;
                            ctx.restart(OUTER);
                            pc = 3;
                            continue;
                        }
                        if (!breakAfterReaction(ctx, OUTER, 12)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void restartInAReactionRestartsTheReactionsBlock(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("outer 0\nouter 1\nouter 2\ndone 3\n",
                    Missions.run(driver, RestartFromReaction.MAIN, 1, RestartFromReaction::new, trace).journal());
            assertEquals(List.of("inner:RESTART", "inner:RESTART", "inner:BREAK", "outer:BREAK", "main:END"),
                    trace.events(TraceEvent.Left.class).stream().map(e -> e.block() + ":" + e.cause()).toList());
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   local event again;
     *   local int rounds = 0;
     *   asynchronous entry work (rounds &lt; 2) {
     *     rounds++;
     *     emit(again);
     *     .logln("never");
     *     react (again) { reelect; }
     *   }
     *   .logln("rounds " + rounds);
     * }
     * </pre>
     */
    static final class ReelectFromReaction extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final Event AGAIN = MAIN.declareLocalEvent("again");
        static final EntryDefinition WORK = MAIN.child("work", Mode.ASYNCHRONOUS);
        static final Reaction WORK_AGAIN = WORK.react(AGAIN);

        private int rounds;

        ReelectFromReaction(TestAgent self) {
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
                    case 1: rounds = 0; pc = 2; continue;
                    case 2: if (!arrive(ctx, WORK, rounds < 2, 3, 7)) return; continue;
                    case 3: rounds++; if (!step(ctx, 4)) return; continue;
                    case 4: ctx.emit(AGAIN); if (!step(ctx, 5)) return; continue;
                    case 5: self.logln("never"); if (!step(ctx, 6)) return; continue;
                    case 6: if (!leave(ctx, WORK, 7)) return; continue;
                    case 7: if (!endOf(ctx, WORK.sequence(), 8)) return; continue;
                    case 8: self.logln("rounds " + rounds); if (!step(ctx, 9)) return; continue;
                    case 9: if (!leave(ctx, MAIN, 10)) return; continue;
                    case 10: if (!endOf(ctx, MAIN.sequence(), 11)) return; continue;
                    case 11: ctx.finish(); return;
                    case 20:
                        // work declares no locals: no reelect flag to set
                        if (!ctx.endReaction()) return;
                        ctx.reelect(WORK);
                        pc = 2;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void reelectInAReactionArrivesAtTheReactionsBlockAgain(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("rounds 2\nrounds 2\n",
                    Missions.run(driver, ReelectFromReaction.MAIN, 2, ReelectFromReaction::new, trace).journal());
            assertEquals(4, trace.events(TraceEvent.Left.class).stream()
                    .filter(e -> e.block().equals("work") && e.cause() == LeaveCause.REELECT).count());
            assertEquals(4, trace.events(TraceEvent.Entered.class).stream().filter(e -> e.block().equals("work")).count());
        }
    }

    /** The reactions run, as {@code event@block of the reaction}, in order. */
    static List<String> reactions(MemoryTrace trace) {
        return trace.events(TraceEvent.EventReacted.class).stream()
                .map(e -> (e.byDefault() ? "default:" : "") + e.event() + "@" + e.block()).toList();
    }

    static List<String> sortedLines(String journal) {
        List<String> lines = new ArrayList<>(Arrays.asList(journal.split("\n")));
        Collections.sort(lines);
        return lines;
    }
}
