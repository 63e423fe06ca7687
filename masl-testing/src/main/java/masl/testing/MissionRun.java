package masl.testing;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.function.Predicate;
import java.util.regex.Pattern;
import masl.runtime.MissionOutcome;
import masl.runtime.trace.TraceEvent;

/**
 * One finished run of a mission: its outcome, journal and trace, and assertions on them. Every
 * failed assertion names the mission and where it ran; one that failed under a seed says how to
 * replay it exactly.
 */
public final class MissionRun {

    private final String mission;
    private final MissionPlatform platform;
    private final MissionOutcome outcome;
    private final List<TraceEvent> trace;
    private final Optional<String> replayHint;

    MissionRun(String mission, MissionPlatform platform, MissionOutcome outcome, List<TraceEvent> trace,
            Optional<String> replayHint) {
        this.mission = mission;
        this.platform = platform;
        this.outcome = outcome;
        this.trace = List.copyOf(trace);
        this.replayHint = replayHint;
    }

    /** Where it ran: the {@link Schedule} of an in-process run, or the agent platform. */
    public MissionPlatform platform() {
        return platform;
    }

    public MissionOutcome outcome() {
        return outcome;
    }

    public String journal() {
        return outcome.journal();
    }

    /** The journal's lines, without their line ends; a last line without {@code \n} counts too. */
    public List<String> journalLines() {
        String journal = journal();
        if (journal.isEmpty()) {
            return List.of();
        }
        List<String> lines = new ArrayList<>(Arrays.asList(journal.split("\n", -1)));
        if (lines.get(lines.size() - 1).isEmpty()) {
            lines.remove(lines.size() - 1);
        }
        return lines;
    }

    /** Every membership change, barrier trip and wave of the run, in the order they happened. */
    public List<TraceEvent> trace() {
        return trace;
    }

    public <T extends TraceEvent> List<T> trace(Class<T> kind) {
        return trace.stream().filter(kind::isInstance).map(kind::cast).toList();
    }

    public MissionRun assertCompleted() {
        if (!outcome.completed()) {
            throw failure("did not complete: " + outcome.status() + "\n" + outcome.report());
        }
        return this;
    }

    /** The journal is exactly {@code expected}; the mission completed. */
    public MissionRun assertJournal(String expected) {
        assertCompleted();
        if (!journal().equals(expected)) {
            throw failure("journal differs\nexpected:\n" + expected + "\nactual:\n" + journal());
        }
        return this;
    }

    /** The journal holds exactly these lines, in any order; the mission completed. */
    public MissionRun assertLinesInAnyOrder(String... expected) {
        assertCompleted();
        List<String> actual = journalLines().stream().sorted().toList();
        List<String> wanted = Arrays.stream(expected).sorted().toList();
        if (!actual.equals(wanted)) {
            throw failure("journal lines differ (in any order)\nexpected:\n" + String.join("\n", wanted)
                    + "\nactual:\n" + journal());
        }
        return this;
    }

    /**
     * Every journal line matching {@code earlier} (a regular expression, whole line) comes before any
     * line matching {@code later}, and each of them matches at least one line.
     */
    public MissionRun assertEveryBefore(String earlier, String later) {
        Predicate<String> first = Pattern.compile(earlier).asMatchPredicate();
        Predicate<String> second = Pattern.compile(later).asMatchPredicate();
        List<String> lines = journalLines();
        int lastFirst = -1;
        int firstSecond = -1;
        for (int i = 0; i < lines.size(); i++) {
            if (first.test(lines.get(i))) {
                lastFirst = i;
            }
            if (second.test(lines.get(i)) && firstSecond < 0) {
                firstSecond = i;
            }
        }
        if (lastFirst < 0 || firstSecond < 0) {
            throw failure("no journal line matches " + (lastFirst < 0 ? earlier : later) + "\njournal:\n" + journal());
        }
        if (lastFirst > firstSecond) {
            throw failure("line " + (lastFirst + 1) + " matching " + earlier + " comes after line " + (firstSecond + 1)
                    + " matching " + later + "\njournal:\n" + journal());
        }
        return this;
    }

    /** Some event of the trace is of {@code kind} and satisfies {@code property}. */
    public <T extends TraceEvent> MissionRun assertTraceHas(Class<T> kind, Predicate<? super T> property, String description) {
        if (trace(kind).stream().noneMatch(property)) {
            throw failure("no " + kind.getSimpleName() + " in the trace " + description);
        }
        return this;
    }

    /** No event of the trace is of {@code kind} and satisfies {@code property}. */
    public <T extends TraceEvent> MissionRun assertTraceHasNo(Class<T> kind, Predicate<? super T> property, String description) {
        trace(kind).stream().filter(property).findFirst().ifPresent(found -> {
            throw failure("the trace has " + found + ", " + description);
        });
        return this;
    }

    AssertionError failure(String what) {
        return new AssertionError(mission + " " + platform + ": " + what + replayHint.map(hint -> "\n" + hint).orElse(""));
    }

    @Override
    public String toString() {
        return mission + " " + platform + ": " + outcome.status();
    }
}
