package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Countermeasures (MASL §9): each agent launches {@code calibrate} (countermeasure
 * {@code stopCalibrate}) in {@code outer} and again in {@code inner}, then leaves in its own way.
 * <pre>
 * asynchronous entry main (true) {
 *   asynchronous entry outer (true) {
 *     local event halt;
 *     .calibrate();
 *     asynchronous entry inner (true) {
 *       .calibrate();
 *       agent 0: break;            agent 1: break(outer);      agent 2: emit halt;
 *       agent 3: (normal end)      agent 4: .stopCalibrate();
 *     }
 *     react (halt) { }             // leaves outer, as break in outer would
 *   }
 * }
 * </pre>
 */
@Timeout(120)
class CountermeasureTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final EntryDefinition OUTER = MAIN.child("outer", Mode.ASYNCHRONOUS);
    static final Event HALT = OUTER.declareLocalEvent("halt");
    static final EntryDefinition INNER = OUTER.child("inner", Mode.ASYNCHRONOUS);
    static final Reaction OUTER_REACT_HALT = OUTER.react(HALT);

    static final class Leaving extends CompactProgram {
        private final Queue<String> stops;

        Leaving(TestAgent self, Queue<String> stops) {
            super(self);
            this.stops = stops;
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            return reaction == OUTER_REACT_HALT ? 30 : super.reactionPc(reaction);
        }

        private Callable<Object> stop(String what) {
            int me = self.getProxyID();
            return () -> {
                stops.add(me + " " + what);
                return null;
            };
        }

        private void calibrate(AgentContext ctx, String block) {
            ctx.launch(self, "calibrate", 0, () -> 0, "stopCalibrate", stop(block));
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 16)) return; continue;
                    case 1: if (!arrive(ctx, OUTER, true, 2, 14)) return; continue;
                    case 2: calibrate(ctx, "outer"); if (!step(ctx, 3)) return; continue;
                    case 3: if (!arrive(ctx, INNER, true, 4, 12)) return; continue;
                    case 4: calibrate(ctx, "inner"); if (!step(ctx, 5)) return; continue;
                    case 5:
                        switch (me) {
                            case 0 -> {
                                ctx.breakOut(INNER);
                                pc = 12;
                            }
                            case 1 -> {
                                ctx.breakOut(OUTER);
                                pc = 14;
                            }
                            case 2 -> {
                                ctx.emit(HALT);
                                if (!step(ctx, 11)) return;
                            }
                            case 3 -> pc = 11;
                            default -> {
                                ctx.invokeSelf("stopCalibrate", null, stop("explicit"));
                                if (!step(ctx, 11)) return;
                            }
                        }
                        continue;
                    case 11: if (!leave(ctx, INNER, 12)) return; continue;
                    case 12: if (!endOf(ctx, INNER.sequence(), 13)) return; continue;
                    case 13: if (!leave(ctx, OUTER, 14)) return; continue;
                    case 14: if (!endOf(ctx, OUTER.sequence(), 15)) return; continue;
                    case 15: if (!leave(ctx, MAIN, 16)) return; continue;
                    case 16: if (!endOf(ctx, MAIN.sequence(), 17)) return; continue;
                    case 17: ctx.finish(); return;
                    case 30: if (!breakAfterReaction(ctx, OUTER, 14)) return; continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void everyWayOfLeavingFiresEachArmedCountermeasureOnceInnermostFirst(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            Queue<String> stops = new ConcurrentLinkedQueue<>();
            MemoryTrace trace = new MemoryTrace();
            Missions.run(driver, MAIN, 5, self -> new Leaving(self, stops), trace);
            assertEquals(List.of("0 inner", "0 outer", "1 inner", "1 outer", "2 inner", "2 outer", "3 inner", "3 outer",
                    "4 explicit"), stops.stream().sorted().toList());
            List<List<String>> fired = new ArrayList<>();
            for (int agent = 0; agent < 5; agent++) {
                fired.add(new ArrayList<>());
            }
            for (TraceEvent.CountermeasureFired event : trace.events(TraceEvent.CountermeasureFired.class)) {
                assertEquals(event.agent(), event.callee());
                assertEquals("stopCalibrate", event.member());
                fired.get(event.agent()).add(event.block());
            }
            List<String> innermostFirst = List.of("inner", "outer");
            assertEquals(List.of(innermostFirst, innermostFirst, innermostFirst, innermostFirst, List.of()), fired);
        }
    }

    /**
     * A fired countermeasure counts as the completion of its launch (§10): {@code calibrate} runs
     * until {@code stopCalibrate} stops it; the agent breaks out of {@code inner} while it runs.
     * <pre>
     * asynchronous entry main (true) {
     *   LLabel l; local int x = 0;
     *   asynchronous entry inner (true) { l.x = .calibrate(); break; }
     *   .logln(l.isFinished() + " x=" + x);
     * }
     * </pre>
     */
    static final class Stopped extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final EntryDefinition INNER = MAIN.child("inner", Mode.ASYNCHRONOUS);

        private final CountDownLatch stopped = new CountDownLatch(1);
        private Label l;
        private int x;

        Stopped(TestAgent self) {
            super(self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 6)) return; continue;
                    case 1:
                        l = ctx.newLabel();
                        x = 0;
                        if (!arrive(ctx, INNER, true, 2, 3)) return;
                        continue;
                    case 2:
                        l.register(ctx.launch(self, "calibrate", -1, () -> {
                            stopped.await();
                            return 5;
                        }, "stopCalibrate", () -> {
                            stopped.countDown();
                            return null;
                        }), v -> x = v);
                        ctx.breakOut(INNER);
                        pc = 3;
                        continue;
                    case 3: if (!endOf(ctx, INNER.sequence(), 4)) return; continue;
                    case 4: self.logln(l.isFinished() + " x=" + x); if (!step(ctx, 5)) return; continue;
                    case 5: if (!leave(ctx, MAIN, 6)) return; continue;
                    case 6: if (!endOf(ctx, MAIN.sequence(), 7)) return; continue;
                    case 7: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aFiredCountermeasureCompletesItsLaunchForLabels(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("true x=-1\n", Missions.run(driver, Stopped.MAIN, 1, Stopped::new).journal());
        }
    }
}
