package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Three deliberate deadlocks from MASL source through {@code masl run}: each ends by
 * itself with exit status 2 and a report naming, for every agent, the MASL line it waits at. The
 * mission's own duration is read from its trace (first record to {@code mission-ended}), so the
 * time to translate and compile does not count; it is printed with the time from the last change.
 */
@Timeout(120)
class DeadlockReportTest {

    /** Each ends within 2 s (measured: 200-300 ms, the watchdog's two looks 100 ms apart). */
    private static final long MISSION_BOUND_NANOS = 2_000_000_000L;

    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path folder;

    @Test
    void aLockedEntryNobodyReleasesIsReportedAtItsEntryLine() throws IOException {
        MaslCommand run = deadlocked("locked_entry.masl");
        for (String agent : List.of("a \\(0\\)", "b \\(1\\)", "c \\(2\\)")) {
            assertReports(run, "agent " + agent + " at pc \\d+ \\(locked_entry.masl:8: synchronous entry gate \\(true\\)\\): "
                    + "\\[main, gate\\(waiting-in\\)\\]");
        }
    }

    @Test
    void aBusyWaitInLockStepIsReportedAtTheLoopAndAMemberOfAnAsynchronousChildAtItsOwn() throws IOException {
        MaslCommand run = deadlocked("busy_wait_in_lock_step.masl");
        assertEquals("working\n", run.out());
        assertReports(run, "agent a \\(0\\) at pc \\d+ \\(busy_wait_in_lock_step.masl:11: while \\(!done\\)\\): \\[main\\]");
        assertReports(run, "agent b \\(1\\) at pc \\d+ \\(busy_wait_in_lock_step.masl:16: while \\(!started\\)\\): \\[main, work\\]");
    }

    @Test
    void twoAgentsWaitingForEachOthersEventsAreReportedAtTheirLoops() throws IOException {
        MaslCommand run = deadlocked("waiting_for_each_other.masl");
        assertReports(run, "agent a \\(0\\) at pc \\d+ \\(waiting_for_each_other.masl:9: while \\(!heard\\)\\): \\[main, first\\]");
        assertReports(run, "agent b \\(1\\) at pc \\d+ \\(waiting_for_each_other.masl:13: while \\(!heard\\)\\): \\[main, second\\]");
    }

    /** Runs the program on the pool (real time), checks the status, the message and the mission's duration. */
    private MaslCommand deadlocked(String program) throws IOException {
        Path trace = folder.resolve(program + ".jsonl");
        MaslCommand run = MaslCommand.run("run", "src/test/resources/faults/" + program, "--trace", trace.toString());
        assertEquals(2, run.status(), run::toString);
        assertTrue(run.err().startsWith("masl: the mission deadlocked: no agent can make progress\n"), run::toString);
        List<JsonNode> records = new ArrayList<>();
        for (String line : Files.readAllLines(trace)) {
            records.add(JSON.readTree(line));
        }
        JsonNode end = records.get(records.size() - 1);
        assertEquals("mission-ended", end.get("event").asText(), records::toString);
        assertEquals("deadlocked", end.get("status").asText());
        long lastChange = records.get(records.size() - 2).get("nanos").asLong();
        long duration = end.get("nanos").asLong() - records.get(0).get("nanos").asLong();
        System.out.printf("%s: deadlock reported %d ms after the start, %d ms after the last change%n", program,
                duration / 1_000_000, (end.get("nanos").asLong() - lastChange) / 1_000_000);
        assertTrue(duration < MISSION_BOUND_NANOS, "the mission took " + duration / 1_000_000 + " ms");
        return run;
    }

    private static void assertReports(MaslCommand run, String lineRegex) {
        assertTrue(run.err().lines().anyMatch(line -> line.matches(lineRegex)), () -> "no line " + lineRegex + " in\n" + run);
    }
}
