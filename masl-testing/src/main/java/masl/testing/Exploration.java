package masl.testing;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.function.Predicate;

/**
 * The runs of one mission under many schedules (seeds, and the real pool), with what a test asks
 * of them: every distinct journal and the schedules that produced it, a property checked on every
 * run with each counter-example's seed, or a run that shows something.
 */
public final class Exploration {

    private static final int COUNTER_EXAMPLES_SHOWN = 5;

    private final String mission;
    private final List<MissionRun> runs;

    Exploration(String mission, List<MissionRun> runs) {
        this.mission = mission;
        this.runs = List.copyOf(runs);
    }

    public List<MissionRun> runs() {
        return runs;
    }

    /** Each distinct journal, in order of first appearance, with the schedules that gave it. */
    public Map<String, List<MissionPlatform>> distinctJournals() {
        Map<String, List<MissionPlatform>> journals = new LinkedHashMap<>();
        for (MissionRun run : runs) {
            journals.computeIfAbsent(run.journal(), journal -> new ArrayList<>()).add(run.platform());
        }
        return journals;
    }

    /**
     * Checks {@code property} (assertions on one run) on every run; fails with the number of runs
     * that violate it and, for the first few, the schedule to replay and the failure.
     */
    public Exploration assertEveryRun(Consumer<MissionRun> property) {
        List<String> counterExamples = new ArrayList<>();
        for (MissionRun run : runs) {
            try {
                property.accept(run);
            } catch (AssertionError violated) {
                counterExamples.add(violated.getMessage());
            }
        }
        if (!counterExamples.isEmpty()) {
            StringBuilder message = new StringBuilder(mission).append(": ").append(counterExamples.size())
                    .append(" of ").append(runs.size()).append(" runs violate the property");
            counterExamples.stream().limit(COUNTER_EXAMPLES_SHOWN).forEach(example -> message.append("\n- ").append(example));
            throw new AssertionError(message.append('\n').append(report()).toString());
        }
        return this;
    }

    /** The first run (in exploration order) that satisfies {@code property}, if any. */
    public Optional<MissionRun> findRun(Predicate<MissionRun> property) {
        return runs.stream().filter(property).findFirst();
    }

    /** Every distinct journal with how many runs gave it and the first schedules that did. */
    public String report() {
        StringBuilder report = new StringBuilder(mission).append(": ").append(runs.size()).append(" runs, ")
                .append(distinctJournals().size()).append(" distinct journals");
        distinctJournals().forEach((journal, schedules) -> report.append("\n--- ").append(schedules.size())
                .append(" run(s), first ").append(schedules.get(0)).append(":\n").append(journal));
        return report.toString();
    }

    @Override
    public String toString() {
        return report();
    }
}
