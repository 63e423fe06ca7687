package masl.runtime.testing;

import java.time.Duration;
import java.util.function.Function;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.AgentType;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.trace.Trace;

/** Runs a test mission of {@link TestAgent}s and insists that it completes. */
public final class Missions {

    /**
     * How often each concurrency test repeats its mission, per driver: 50, or the system property
     * {@code masl.repetitions} for stress runs.
     */
    public static final int REPETITIONS = Integer.getInteger("masl.repetitions", 50);

    private static final Duration TIMEOUT = Duration.ofSeconds(20);

    private Missions() {
    }

    public static MissionOutcome run(Driver driver, EntryDefinition main, int agents,
            Function<TestAgent, AgentProgram> program) {
        return run(driver, main, agents, program, Trace.NONE);
    }

    public static MissionOutcome run(Driver driver, EntryDefinition main, int agents,
            Function<TestAgent, AgentProgram> program, Trace trace) {
        return run(driver.newScheduler(), main, agents, program, trace);
    }

    public static MissionOutcome run(Scheduler scheduler, EntryDefinition main, int agents,
            Function<TestAgent, AgentProgram> program, Trace trace) {
        return run(scheduler, main, agents, null, program, trace);
    }

    /** A mission whose agents have {@code type} (null: no type, everything allowed), from its descriptor. */
    public static MissionOutcome run(Scheduler scheduler, EntryDefinition main, int agents, AgentType type,
            Function<TestAgent, AgentProgram> program, Trace trace) {
        Mission.Builder builder = Mission.builder().main(main).scheduler(scheduler).trace(trace);
        for (int i = 0; i < agents; i++) {
            builder.agent("a" + i, new TestAgent(), type, program);
        }
        try {
            return builder.build().run(TIMEOUT).requireCompleted();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", e);
        }
    }
}
