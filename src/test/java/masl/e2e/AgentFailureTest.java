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
 * Faults of agents from MASL source through {@code masl run}: a primitive that throws, and
 * an agent whose program dies while the others go on.
 */
@Timeout(120)
class AgentFailureTest {

    /** The test's own classes hold the implementation of {@code agents/Faulty.xml}. */
    private static final String TEST_CLASSES = "build/classes/java/test";

    @TempDir
    Path folder;

    @Test
    void aPrimitiveThatThrowsGivesUncaughtExceptionAndTheDefaultValue() {
        MaslCommand run = MaslCommand.run("run", "src/test/resources/faults/throwing_primitive.masl",
                "--agent-path", TEST_CLASSES, "--seed", "1");
        assertEquals(0, run.status(), run::toString);
        // Each agent reacts at the step boundary of the call, before the next instruction (lock-step).
        assertEquals("uncaught java.lang.IllegalStateException\nuncaught java.lang.IllegalStateException\nr=0\nr=0\n",
                run.out());
    }

    @Test
    void aPrimitiveThatHangsPastTheCallTimeoutGivesTimeoutAndTheDefaultValueAndTheMissionGoesOn() {
        MaslCommand run = MaslCommand.run("run", "src/test/resources/faults/hanging_primitive.masl",
                "--agent-path", TEST_CLASSES, "--call-timeout", "100", "--seed", "1");
        assertEquals(0, run.status(), run::toString);
        // In lock-step: both agents' timeouts at the step boundary of each call, then the next instruction.
        assertEquals("timeout hang\ntimeout hang\nafter hang r=0\nafter hang r=0\n"
                + "timeout hang\ntimeout hang\nafter external hang r=0\nafter external hang r=0\n", run.out());
    }

    @Test
    void aCallTimeoutIsAPositiveNumberOfMilliseconds() {
        MaslCommand run = MaslCommand.run("run", "src/test/resources/faults/hanging_primitive.masl", "--call-timeout", "0");
        assertEquals(64, run.status(), run::toString);
        assertTrue(run.err().startsWith("masl: --call-timeout must be at least 1, got 0\n"), run::toString);
    }

    @Test
    void anAgentWhoseProgramDiesLeavesItsBlockAndTheOthersFinishInLockStep() throws IOException {
        Path trace = folder.resolve("dying.jsonl");
        MaslCommand run = MaslCommand.run("run", "src/test/resources/faults/dying_agent.masl", "--trace", trace.toString());

        assertEquals(2, run.status(), run::toString);
        assertTrue(run.err().startsWith("masl: the mission failed\n"
                + "  java.lang.IllegalStateException: agent b (1) at pc "), run::toString);
        assertTrue(run.err().contains("(dying_agent.masl:8: i = i / zero;) failed\n"
                + "  caused by java.lang.ArithmeticException: / by zero\n"), run::toString);
        List<String> journal = run.out().lines().toList();
        for (String line : List.of("0:0", "0:1", "0:2", "1:0", "2:0", "2:1", "2:2")) {
            assertTrue(journal.contains(line), run::toString);
        }
        assertEquals(7, journal.size(), run::toString);

        List<JsonNode> records = new ArrayList<>();
        for (String line : Files.readAllLines(trace)) {
            records.add(new ObjectMapper().readTree(line));
        }
        int failed = indexOf(records, "agent-failed");
        JsonNode failure = records.get(failed);
        assertEquals(1, failure.get("agent").asInt());
        assertEquals("java.lang.ArithmeticException: / by zero", failure.get("cause").asText());
        assertEquals(8, failure.get("line").asInt());
        JsonNode left = records.get(failed + 1);
        assertEquals("left", left.get("event").asText(), left::toString);
        assertEquals("failed", left.get("cause").asText(), left::toString);
        assertEquals("main", left.get("block").asText(), left::toString);
        // The barrier shrinks: every trip after the failure is of the two others.
        records.subList(failed, records.size()).stream()
                .filter(record -> record.get("event").asText().equals("barrier-tripped"))
                .forEach(trip -> assertEquals(2, trip.get("agents").asInt(), trip::toString));
        assertEquals("failed", records.get(records.size() - 1).get("status").asText());
    }

    private static int indexOf(List<JsonNode> records, String event) {
        for (int i = 0; i < records.size(); i++) {
            if (records.get(i).get("event").asText().equals(event)) {
                return i;
            }
        }
        throw new AssertionError("no " + event + " in " + records);
    }
}
