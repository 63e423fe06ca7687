package masl.e2e;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.LongStream;
import masl.runtime.MissionOutcome;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.Schedule;

/**
 * The journal of a lock-step program, step by step: the lines written in one step come in any
 * order, those of a later step after them all. Written as text, a blank line between two steps:
 *
 * <pre>
 * 2 after kid
 *
 * 0 after kid
 * 1 after kid
 * </pre>
 *
 * {@link #assertEverySchedule} checks it on every run of a mission under seeds, on the pool and with
 * a thread per agent.
 */
final class StepJournal {

    private final List<List<String>> steps = new ArrayList<>();
    private final MissionOutcome.Status status;

    private StepJournal(String text, MissionOutcome.Status status) {
        for (String step : text.split("\n\n")) {
            steps.add(Arrays.stream(step.split("\n")).sorted().toList());
        }
        this.status = status;
    }

    /** The journal of a mission that completes. */
    static StepJournal of(String text) {
        return new StepJournal(text, MissionOutcome.Status.COMPLETED);
    }

    /** The journal of a mission that ends with {@code status} (an agent that dies makes it {@code FAILED}). */
    static StepJournal endingAs(MissionOutcome.Status status, String text) {
        return new StepJournal(text, status);
    }

    /** Runs {@code mission} under seeds 0 to {@code seeds - 1}, then on the pool and with threads, and checks each run. */
    void assertEverySchedule(MaslMission mission, int seeds, int poolRuns, int threadRuns) {
        mission.explore(LongStream.range(0, seeds), poolRuns).assertEveryRun(this::assertRun);
        for (int i = 0; i < threadRuns; i++) {
            assertRun(mission.runWith(Schedule.threads()));
        }
    }

    void assertRun(MissionRun run) {
        if (run.outcome().status() != status) {
            throw new AssertionError(run + ", expected " + status + "\n" + run.outcome().report() + "\njournal:\n" + run.journal());
        }
        List<String> lines = run.journalLines();
        int from = 0;
        for (List<String> step : steps) {
            int to = Math.min(from + step.size(), lines.size());
            if (!lines.subList(from, to).stream().sorted().toList().equals(step)) {
                throw new AssertionError(run + ": the step from line " + (from + 1) + " differs\nexpected, in any order:\n"
                        + String.join("\n", step) + "\njournal:\n" + run.journal());
            }
            from = to;
        }
        if (from != lines.size()) {
            throw new AssertionError(run + ": more lines than expected\njournal:\n" + run.journal());
        }
    }
}
