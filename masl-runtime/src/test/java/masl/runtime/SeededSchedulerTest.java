package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.PhaseLog;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** A seeded run is reproducible: same seed, same trace and journal. */
@Timeout(60)
class SeededSchedulerTest {

    @Test
    void theSameSeedGivesTheSameRunAndSeedsExploreDifferentRuns() {
        Set<List<String>> distinctRuns = new HashSet<>();
        for (long seed = 0; seed < 20; seed++) {
            List<String> first = run(seed);
            assertEquals(first, run(seed), "seed " + seed);
            distinctRuns.add(first);
        }
        // Nine agents joining and leaving a locked block one by one: interleavings differ.
        assertTrue(distinctRuns.size() > 1, "every seed gave the same run");
    }

    private static List<String> run(long seed) {
        MemoryTrace memory = new MemoryTrace();
        PhaseLog log = new PhaseLog("group", memory);
        SynchronousBlockTest.JOIN_AND_LEAVE.run(new SeededScheduler(seed), log, () -> new TestAgent(log));
        // Events without their time stamps, and the phases of the block's instructions.
        List<String> run = new ArrayList<>(memory.events().stream()
                .map(event -> event.toString().replaceAll("nanos=\\d+, ", "")).toList());
        run.add(log.phases().toString());
        return run;
    }

    /** An hour of sleep ends well within the run's timeout of 20 s: on the virtual clock. */
    @Test
    void sleepsTakeVirtualTime() {
        MaslProgram.of("sleeper.masl", MaslProgram.header(1) + """
                asynchronous entry main (true) { Thread.sleep(3600000); }
                """).run(new SeededScheduler(7), Trace.NONE);
    }
}
