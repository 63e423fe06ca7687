package masl.runtime.examples;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.lang.reflect.RecordComponent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReferenceArray;
import java.util.function.Function;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.MissionOutcome;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.TestTypes;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The hand-translated examples E1 to E8 (the worked examples of the generated-code contract, which
 * the JADE bridge's tests run again) are what the translator makes of examples.md's files
 * ({@code src/test/resources/examples} of the project): under each of 10 seeds, the hand-translated
 * program and the translated one give the same journal and the same trace, step for step (times,
 * the MASL statements of the records and the agents' names aside, which hand-written programs lack).
 */
@Timeout(120)
class HandTranslationTest {

    private static final Path EXAMPLES = Path.of("..", "src", "test", "resources", "examples");

    @ParameterizedTest
    @ValueSource(strings = {"e1_scalar_main", "e2_shared_and_local", "e3_asynchronous_child", "e4_events",
        "e5_permeability", "e6_one_at_a_time", "e7_reelect", "e8_break_out_of_two"})
    void theHandTranslationRunsStepForStepAsTheTranslatorsUnderEverySeed(String example) throws IOException {
        MaslProgram translated = MaslProgram.of(example + ".masl", Files.readString(EXAMPLES.resolve(example + ".masl")));
        for (long seed = 1; seed <= 10; seed++) {
            MemoryTrace handTrace = new MemoryTrace();
            String handJournal = runByHand(example, seed, handTrace).journal();
            MemoryTrace trace = new MemoryTrace();
            String journal = translated.run(new SeededScheduler(seed), trace).journal();
            assertEquals(journal, handJournal, example + " under seed " + seed);
            assertEquals(steps(trace), steps(handTrace), example + " under seed " + seed);
        }
    }

    private static MissionOutcome runByHand(String example, long seed, MemoryTrace trace) {
        SeededScheduler scheduler = new SeededScheduler(seed);
        return switch (example) {
            case "e1_scalar_main" -> run(scheduler, E1ScalarMain.MAIN, 3, E1ScalarMain::new, trace);
            case "e2_shared_and_local" -> run(scheduler, E2SharedAndLocal.MAIN, 5, E2SharedAndLocal::new, trace);
            case "e3_asynchronous_child" -> run(scheduler, E3AsynchronousChild.MAIN, 4, E3AsynchronousChild::new, trace);
            case "e4_events" -> run(scheduler, E4Events.MAIN, 4, E4Events::new, trace);
            case "e5_permeability" -> {
                AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(2);
                yield Missions.run(scheduler, E5Permeability.MAIN, 2, TestTypes.testAgent(),
                        self -> new E5Permeability(self, population), trace);
            }
            case "e6_one_at_a_time" -> run(scheduler, E6OneAtATime.MAIN, 4, E6OneAtATime::new, trace);
            case "e7_reelect" -> run(scheduler, E7Reelect.MAIN, 3, E7Reelect::new, trace);
            case "e8_break_out_of_two" -> run(scheduler, E8BreakOutOfTwo.MAIN, 2, E8BreakOutOfTwo::new, trace);
            default -> throw new IllegalArgumentException(example);
        };
    }

    /** The translated program's agents have the tests' root type: so do the hand-translated ones here. */
    private static MissionOutcome run(SeededScheduler scheduler, EntryDefinition main, int agents,
            Function<TestAgent, AgentProgram> program, MemoryTrace trace) {
        return Missions.run(scheduler, main, agents, TestTypes.testAgent(), program, trace);
    }

    /** Each record as its kind and fields, without its time, its statement and the agents' names. */
    private static List<String> steps(MemoryTrace trace) {
        List<String> steps = new ArrayList<>();
        for (TraceEvent event : trace.events()) {
            if (event instanceof TraceEvent.MissionStarted) {
                continue;
            }
            StringBuilder step = new StringBuilder(event.getClass().getSimpleName());
            for (RecordComponent component : event.getClass().getRecordComponents()) {
                if (!component.getName().equals("nanos") && !component.getName().equals("source")) {
                    try {
                        step.append(' ').append(component.getName()).append('=').append(component.getAccessor().invoke(event));
                    } catch (ReflectiveOperationException e) {
                        throw new IllegalStateException(e);
                    }
                }
            }
            steps.add(step.toString());
        }
        return steps;
    }
}
