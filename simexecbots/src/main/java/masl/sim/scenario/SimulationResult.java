package masl.sim.scenario;

import java.nio.file.Path;
import java.util.List;
import masl.runtime.MissionOutcome;
import masl.sim.output.RunRecorder;

/**
 * The end of a scenario run: the mission's outcome (journal included), how much simulated time
 * passed, the recorded trajectories and events, the runtime trace as JSON lines, the files
 * written (empty without an output folder), and whether the trace was cut at its limit
 * ({@link RunOptions#traceLimit()}).
 */
public record SimulationResult(MissionOutcome outcome, double simulatedSeconds, RunRecorder recorder, String trace,
        List<Path> files, boolean traceCut) {

    public SimulationResult {
        files = List.copyOf(files);
    }

    /** {@code trajectories.csv} as text. */
    public String trajectoriesCsv() {
        StringBuilder csv = new StringBuilder();
        recorder.writeTrajectoriesCsv(csv);
        return csv.toString();
    }

    /** {@code events.jsonl} as text. */
    public String eventsJsonLines() {
        StringBuilder lines = new StringBuilder();
        recorder.writeEventsJsonLines(lines);
        return lines.toString();
    }
}
