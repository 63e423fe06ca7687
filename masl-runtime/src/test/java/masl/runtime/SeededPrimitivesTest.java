package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.JsonLinesTrace;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A seeded run is reproducible with asynchronous primitives too: their bodies are tasks the seeded
 * scheduler draws, so the journal they write and the moments their launches complete are the
 * seed's. Four agents each launch {@code calibrate} with the countermeasure {@code stopCalibrate},
 * and agent 0 collects three launches of {@code measure} on the others with a label.
 */
@Timeout(120)
class SeededPrimitivesTest {

    /** {@code calibrate} logs "i calibrates", its countermeasure "i stops", {@code measure} "j measures" and gives 10 * j. */
    private static final MaslProgram LAUNCHES = MaslProgram.of("launches.masl", 4, """
            asynchronous entry main (true) {
              asynchronous entry work (true) {
                LLabel l;
                local int x1 = 0;
                local int x2 = 0;
                local int x3 = 0;
                .calibrate();
                if (.getProxyID() == 0) {
                  l.x1 = a1.measure(); l.x2 = a2.measure(); l.x3 = a3.measure();
                  while (!l.isFinished()) {}
                  .logln("0 got " + x1 + " " + x2 + " " + x3);
                } else {
                  .logln(.getProxyID() + " works");
                }
                break;
              }
            }
            """);

    @Test
    void theSameSeedGivesTheSameTraceAndJournalByteForByte() {
        for (long seed : new long[] {3, 17}) {
            String first = run(seed);
            for (int run = 1; run < Missions.REPETITIONS; run++) {
                assertEquals(first, run(seed), "seed " + seed + ", run " + run);
            }
        }
    }

    @Test
    void differentSeedsGiveDifferentOrdersWithTheSameOutcome() {
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
     * waits for it: it is left to go on alone, and the mission completes. Here {@code measure}
     * awaits a latch that the agent's {@code signal} opens, then gives 7.
     */
    private static final MaslProgram WAITING_BODY = MaslProgram.of("waiting.masl", 1, """
            scalar entry main (true) {
              local int got = .measure();
              .signal(0);
              .logln("got " + got);
            }
            """);

    /** Measures once its own agent has signalled. */
    private static final class Gated extends TestAgent {
        private final CountDownLatch gate = new CountDownLatch(1);

        @Override
        public int measure() {
            awaitOpening(gate);
            return 7;
        }

        @Override
        public int signal(int value) {
            gate.countDown();
            return value;
        }
    }

    @Test
    void aBodyWaitingForItsAgentGoesOnAloneAndTheRunCompletes() {
        for (long seed = 0; seed < 20; seed++) {
            assertEquals("got 7\n", WAITING_BODY.run(new SeededScheduler(seed), Trace.NONE, Gated::new).journal(),
                    "seed " + seed);
        }
    }

    /** The journal, a separator line, then the trace as JSON lines (virtual time stamps included). */
    private static String run(long seed) {
        StringBuilder trace = new StringBuilder();
        String journal = LAUNCHES.run(new SeededScheduler(seed), new JsonLinesTrace(trace)).journal();
        return journal + "--\n" + trace;
    }

    private static String journalOf(String run) {
        return run.substring(0, run.indexOf("--\n"));
    }
}
