package masl.sim.scenario;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.DoubleConsumer;
import masl.runtime.Mission;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.trace.JsonLinesTrace;
import masl.runtime.trace.Trace;

/**
 * How {@link ScenarioRunner} runs a scenario, besides what the scenario itself says.
 *
 * @param timeout   wall-clock limit of the run (the scenario's {@code duration} limits simulated time)
 * @param journal   where the mission journal is written as it grows, or null for nowhere but the result
 * @param trace     the runtime's trace of memberships and barriers, as the runtime stamps it (wall-clock
 *                  nanoseconds); {@code trace.jsonl} and {@link SimulationResult#trace()} carry simulated time
 * @param output    a folder to write {@code trajectories.csv}, {@code events.jsonl}, {@code trace.jsonl},
 *                  {@code journal.txt} and {@code trajectories.png} to, created if missing
 * @param classes   loads the implementation and initialisation classes the scenario names, or null
 *                  for the mission program's own class loader
 * @param ready     given the mission once it is built, before it runs: whoever may stop it early
 *                  (on a signal, say) keeps it
 * @param progress  told the simulated time, in seconds, after every physics step (on the stepping
 *                  thread: it must be quick), for a progress report
 * @param traceLimit the size in bytes at which {@code trace.jsonl} is cut ({@link JsonLinesTrace})
 * @param warned    given the warnings of the XODE files loaded (worlds and bodies; a body several robots
 *                  share, once), each with its file, line and column, before the mission runs; not
 *                  called when there are none
 */
public record RunOptions(Duration timeout, Appendable journal, Trace trace, Optional<Path> output, ClassLoader classes,
        Consumer<Mission> ready, DoubleConsumer progress, long traceLimit, Consumer<List<Diagnostic>> warned) {

    public RunOptions {
        Objects.requireNonNull(timeout, "timeout");
        Objects.requireNonNull(trace, "trace");
        Objects.requireNonNull(output, "output");
        Objects.requireNonNull(ready, "ready");
        Objects.requireNonNull(progress, "progress");
        Objects.requireNonNull(warned, "warned");
    }

    /**
     * Ten minutes, no journal sink, no trace, no output files, the program's class loader, no
     * progress, a trace of at most 1 GiB, warnings ignored.
     */
    public static RunOptions defaults() {
        return new RunOptions(Duration.ofMinutes(10), null, Trace.NONE, Optional.empty(), null, mission -> { }, seconds -> { },
                JsonLinesTrace.DEFAULT_LIMIT, warnings -> { });
    }

    public RunOptions whenReady(Consumer<Mission> action) {
        return new RunOptions(timeout, journal, trace, output, classes, action, progress, traceLimit, warned);
    }

    public RunOptions withTimeout(Duration newTimeout) {
        return new RunOptions(newTimeout, journal, trace, output, classes, ready, progress, traceLimit, warned);
    }

    public RunOptions withJournal(Appendable sink) {
        return new RunOptions(timeout, sink, trace, output, classes, ready, progress, traceLimit, warned);
    }

    public RunOptions withTrace(Trace newTrace) {
        return new RunOptions(timeout, journal, newTrace, output, classes, ready, progress, traceLimit, warned);
    }

    public RunOptions withOutput(Path folder) {
        return new RunOptions(timeout, journal, trace, Optional.of(folder), classes, ready, progress, traceLimit, warned);
    }

    public RunOptions withClasses(ClassLoader loader) {
        return new RunOptions(timeout, journal, trace, output, loader, ready, progress, traceLimit, warned);
    }

    public RunOptions withProgress(DoubleConsumer simulatedSeconds) {
        return new RunOptions(timeout, journal, trace, output, classes, ready, simulatedSeconds, traceLimit, warned);
    }

    /** Cuts {@code trace.jsonl} at {@code bytes}, at least {@link JsonLinesTrace#MIN_LIMIT}. */
    public RunOptions withTraceLimit(long bytes) {
        return new RunOptions(timeout, journal, trace, output, classes, ready, progress, bytes, warned);
    }

    public RunOptions whenWarned(Consumer<List<Diagnostic>> action) {
        return new RunOptions(timeout, journal, trace, output, classes, ready, progress, traceLimit, action);
    }
}
