package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.testing.PhaseLog;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** A seeded run is reproducible: same seed, same trace and journal. */
@Timeout(60)
class SeededSchedulerTest {

    @Test
    void theSameSeedGivesTheSameRunAndSeedsExploreDifferentRuns() throws InterruptedException {
        Set<List<String>> distinctRuns = new HashSet<>();
        for (long seed = 0; seed < 20; seed++) {
            List<String> first = run(seed);
            assertEquals(first, run(seed), "seed " + seed);
            distinctRuns.add(first);
        }
        // Nine agents joining and leaving a locked block one by one: interleavings differ.
        assertTrue(distinctRuns.size() > 1, "every seed gave the same run");
    }

    private static List<String> run(long seed) throws InterruptedException {
        MemoryTrace memory = new MemoryTrace();
        PhaseLog log = new PhaseLog("group", memory);
        Function<TestAgent, AgentProgram> program = self -> new SynchronousBlockTest.JoinAndLeave(self, log);
        Mission.Builder builder = Mission.builder().main(SynchronousBlockTest.JoinAndLeave.MAIN)
                .scheduler(new SeededScheduler(seed)).trace(log);
        for (int i = 0; i <= SynchronousBlockTest.JoinAndLeave.MEMBERS; i++) {
            builder.agent("a" + i, new TestAgent(), program);
        }
        builder.build().run(Duration.ofSeconds(20)).requireCompleted();
        // Events without their time stamps, and the phases of the block's instructions.
        List<String> run = new ArrayList<>(memory.events().stream()
                .map(event -> event.toString().replaceAll("nanos=\\d+, ", "")).toList());
        run.add(log.phases().toString());
        return run;
    }

    /** An hour of sleep ends well within the run's timeout of 20 s: on the virtual clock. */
    @Test
    void sleepsTakeVirtualTime() throws InterruptedException {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        Mission.builder().main(main).scheduler(new SeededScheduler(7))
                .agent("sleeper", new TestAgent(), self -> new AgentProgram() {
                    @Override
                    @SuppressWarnings("fallthrough") // resumption points fall through into the next one
                    protected void resume(AgentContext ctx) {
                        while (true) {
                            switch (pc) {
                                case 0: pc = 1; if (!ctx.sleep(Duration.ofHours(1).toMillis())) return;
                                case 1: ctx.finish(); return;
                                default: throw new IllegalStateException("pc " + pc);
                            }
                        }
                    }
                }).build().run(Duration.ofSeconds(20)).requireCompleted();
    }
}
