package masl.sim.scenario;

import java.nio.file.Path;
import java.util.List;
import masl.runtime.MissionOutcome;
import masl.sim.output.RunRecorder;

/**
 * The end of a scenario run: the mission's outcome (journal included), how much simulated time
 * passed, the recorded trajectories and events, the runtime trace as JSON lines, and the files
 * written (empty without an output folder).
 */
public record SimulationResult(MissionOutcome outcome, double simulatedSeconds, RunRecorder recorder, String trace,
        List<Path> files) {

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
