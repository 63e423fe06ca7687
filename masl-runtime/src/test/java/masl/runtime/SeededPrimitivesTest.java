package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.JsonLinesTrace;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A seeded run is reproducible with asynchronous primitives too: their bodies are tasks the seeded
 * scheduler draws, so the journal they write and the moments their launches complete are the
 * seed's. Four agents each launch {@code calibrate} with the countermeasure {@code stopCalibrate},
 * and agent 0 collects three launches of {@code measure} on the others with a label.
 * <pre>
 * asynchronous entry main (true) {
 *   asynchronous entry work (true) {
 *     .calibrate();                                  // logs "i calibrates"; countermeasure stopCalibrate logs "i stops"
 *     if (me == 0) {
 *       LLabel l;
 *       l.x1 = a1.measure(); l.x2 = a2.measure(); l.x3 = a3.measure();   // "j measures", 10 * j
 *       while (!l.isFinished()) {}
 *       .logln("0 got " + x1 + " " + x2 + " " + x3);
 *     } else {
 *       .logln(me + " works");
 *     }
 *     break;                                         // fires stopCalibrate
 *   }
 * }
 * </pre>
 */
@Timeout(120)
class SeededPrimitivesTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final EntryDefinition WORK = MAIN.child("work", Mode.ASYNCHRONOUS);
    private static final int AGENTS = 4;

    static final class Launches extends CompactProgram {
        private final AtomicReferenceArray<TestAgent> population;
        private Label l;
        private int x1;
        private int x2;
        private int x3;

        Launches(TestAgent self, AtomicReferenceArray<TestAgent> population) {
            super(self);
            this.population = population;
            population.set(self.getProxyID(), self);
        }

        private static <T> Callable<T> logging(TestAgent agent, String what, T result) {
            return () -> {
                agent.logln(agent.getProxyID() + " " + what);
                return result;
            };
        }

        private CompletableFuture<Integer> measure(AgentContext ctx, int agent) {
            TestAgent callee = population.get(agent);
            return ctx.launch(callee, "measure", 0, logging(callee, "measures", 10 * agent));
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 20)) return; continue;
                    case 1: if (!arrive(ctx, WORK, true, 2, 18)) return; continue;
                    case 2:
                        ctx.launch(self, "calibrate", false, logging(self, "calibrates", true),
                                "stopCalibrate", logging(self, "stops", null));
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3:
                        if (me != 0) {
                            self.logln(me + " works");
                            if (!step(ctx, 10)) return;
                            continue;
                        }
                        l = ctx.newLabel();
                        l.register(measure(ctx, 1), v -> x1 = v);
                        l.register(measure(ctx, 2), v -> x2 = v);
                        l.register(measure(ctx, 3), v -> x3 = v);
                        if (!step(ctx, 4)) return;
                        continue;
                    case 4: if (!busyWait(ctx, !l.isFinished(), 5)) return; continue;
                    case 5:
                        self.logln("0 got " + x1 + " " + x2 + " " + x3);
                        if (!step(ctx, 10)) return;
                        continue;
                    case 10:
                        ctx.breakOut(WORK);
                        pc = 18;
                        continue;
                    case 18: if (!endOf(ctx, WORK.sequence(), 19)) return; continue;
                    case 19: if (!leave(ctx, MAIN, 20)) return; continue;
                    case 20: if (!endOf(ctx, MAIN.sequence(), 21)) return; continue;
                    case 21: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @Test
    void theSameSeedGivesTheSameTraceAndJournalByteForByte() throws InterruptedException {
        for (long seed : new long[] {3, 17}) {
            String first = run(seed);
            for (int run = 1; run < Missions.REPETITIONS; run++) {
                assertEquals(first, run(seed), "seed " + seed + ", run " + run);
            }
        }
    }

    @Test
    void differentSeedsGiveDifferentOrdersWithTheSameOutcome() throws InterruptedException {
        Set<String> journals = new HashSet<>();
        for (long seed = 0; seed < 10; seed++) {
            String journal = journalOf(run(seed));
            List<String> lines = journal.lines().sorted().toList();
            assertEquals(List.of("0 calibrates", "0 got 10 20 30", "0 stops", "1 calibrates", "1 measures", "1 stops",
                    "1 works", "2 calibrates", "2 measures", "2 stops", "2 works", "3 calibrates", "3 measures",
                    "3 stops", "3 works"), lines, "seed " + seed);
            journals.add(journal);
        }
        assertTrue(journals.size() > 1, "every seed ran the primitives in the same order");
    }

    /**
     * A body that waits for its own agent to do something cannot finish while the one seeded thread
     * waits for it: it is left to go on alone, and the mission completes.
     * <pre>
     * scalar entry main (true) {
     *   local int got = .waitForGate();   // an asynchronous primitive: awaits a latch, then 7
     *   .openGate();                      // the agent opens the latch
     *   .logln("got " + got);             // reads the future
     * }
     * </pre>
     */
    @Test
    void aBodyWaitingForItsAgentGoesOnAloneAndTheRunCompletes() throws InterruptedException {
        EntryDefinition main = EntryDefinition.main("main", Mode.SCALAR);
        for (long seed = 0; seed < 20; seed++) {
            CountDownLatch gate = new CountDownLatch(1);
            MissionOutcome outcome = Mission.builder().main(main).scheduler(new SeededScheduler(seed))
                    .agent("a", new TestAgent(), self -> new CompactProgram(self) {
                        private CompletableFuture<Integer> got;

                        @Override
                        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
                        protected void resume(AgentContext ctx) {
                            while (true) {
                                switch (pc) {
                                    case 0: if (!arrive(ctx, main, true, 1, 5)) return; continue;
                                    case 1:
                                        got = ctx.launch(self, "waitForGate", 0, () -> {
                                            gate.await();
                                            return 7;
                                        });
                                        if (!step(ctx, 2)) return;
                                        continue;
                                    case 2:
                                        gate.countDown();
                                        pc = 3;
                                        if (!ctx.await(got)) return;
                                    case 3:
                                        self.logln("got " + got.join());
                                        if (!step(ctx, 4)) return;
                                        continue;
                                    case 4: if (!leave(ctx, main, 5)) return; continue;
                                    case 5: if (!endOf(ctx, main.sequence(), 6)) return; continue;
                                    case 6: ctx.finish(); return;
                                    default: throw new IllegalStateException("pc " + pc);
                                }
                            }
                        }
                    }).build().run(Duration.ofSeconds(20));
            assertEquals("got 7\n", outcome.requireCompleted().journal(), "seed " + seed);
        }
    }

    /** The journal, a separator line, then the trace as JSON lines (virtual time stamps included). */
    private static String run(long seed) throws InterruptedException {
        StringBuilder journal = new StringBuilder();
        StringBuilder trace = new StringBuilder();
        AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(AGENTS);
        Mission.Builder builder = Mission.builder().main(MAIN).scheduler(new SeededScheduler(seed))
                .journal(journal).trace(new JsonLinesTrace(trace));
        for (int i = 0; i < AGENTS; i++) {
            builder.agent("a" + i, new TestAgent(), self -> new Launches(self, population));
        }
        builder.build().run(Duration.ofSeconds(20)).requireCompleted();
        return journal + "--\n" + trace;
    }

    private static String journalOf(String run) {
        return run.substring(0, run.indexOf("--\n"));
    }
}
