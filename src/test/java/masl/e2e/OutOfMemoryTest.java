package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A mission whose data grows for ever, in a JVM of 64 or 128 MiB: the heap's exhaustion fails the
 * mission as any failure does (status 2, where the agents were, a complete trace), never as an
 * internal error or a thread's stack trace; a timeout that comes while the heap runs low ends it as
 * a timeout does. A program too large for the heap to translate is said to be so (status 71).
 */
@Timeout(300)
@Tag("slow")
class OutOfMemoryTest {

    @TempDir
    Path folder;

    private static final String GROW = """
            import Default.xml as Default;
            Default a, b = newAgent(Default);
            asynchronous entry main (true) {
              local Vector kept = new Vector();
              while (true) {
                kept.add("some text that takes room " + kept.size());
              }
            }
            """;

    @Test
    void aProgramThatExhaustsTheHeapFailsTheMissionWithItsReportAndACompleteTrace() throws Exception {
        Path program = Files.writeString(folder.resolve("grow.masl"), GROW);
        Path trace = folder.resolve("grow.jsonl");

        try (MaslProcess masl = MaslProcess.startWith(List.of("-Xmx64m"), folder.resolve("journal.txt").toFile(),
                "run", program.toString(), "--trace", trace.toString(), "--quiet", "--timeout", "240")) {
            assertEquals(2, masl.awaitExit(), masl::toString);
            String err = masl.err();
            assertTrue(err.startsWith("masl: the mission ran out of memory: its data outgrew the heap's "), err);
            // Where each agent was, with its MASL line, as the report of any failed mission says.
            assertTrue(err.lines().anyMatch(line -> line.matches("agent a \\(0\\) at pc \\d+ \\(grow\\.masl:[56]: .*")), err);
            assertTrue(err.lines().anyMatch(line -> line.matches("agent b \\(1\\) at pc \\d+ \\(grow\\.masl:[56]: .*")), err);
            assertFalse(err.contains("Exception in thread"), err);
            assertFalse(err.contains("internal error"), err);
        }
        JsonNode last = CompleteTrace.lastRecord(trace);
        assertEquals("mission-ended", last.get("event").asText(), last::toString);
        assertEquals("failed", last.get("status").asText(), last::toString);
    }

    /**
     * A timeout of two seconds, which comes while the data fills the heap or just after it is full:
     * whichever ends the mission first, the report says it, the trace's last record agrees, and
     * neither a thread's stack trace nor an internal error is printed.
     */
    @Test
    void aTimeoutWhileTheHeapRunsLowEndsTheMissionAsTheTraceSays() throws Exception {
        Path program = Files.writeString(folder.resolve("grow.masl"), GROW);
        Path trace = folder.resolve("grow.jsonl");

        try (MaslProcess masl = MaslProcess.startWith(List.of("-Xmx128m"), folder.resolve("journal.txt").toFile(),
                "run", program.toString(), "--trace", trace.toString(), "--quiet", "--timeout", "2")) {
            assertEquals(2, masl.awaitExit(), masl::toString);
            String err = masl.err();
            JsonNode last = CompleteTrace.lastRecord(trace);
            assertEquals("mission-ended", last.get("event").asText(), last::toString);
            String ended = last.get("status").asText();
            if (ended.equals("timed_out")) {
                assertTrue(err.startsWith("masl: the mission timed out\n"), err);
            } else {
                assertEquals("failed", ended, last::toString);
                assertTrue(err.startsWith("masl: the mission ran out of memory: "), err);
            }
            assertTrue(err.lines().anyMatch(line -> line.matches("agent a \\(0\\) at pc \\d+ \\(grow\\.masl:\\d+: .*")), err);
            assertFalse(err.contains("Exception in thread"), err);
            assertFalse(err.contains("\tat "), err);
            assertFalse(err.contains("internal error"), err);
        }
    }

    /** Translating a program of 200,000 statements in a heap of 32 MiB: out of memory, said so, no bug of masl. */
    @Test
    void aProgramTooLargeForTheHeapIsSaidToBeSoWithItsOwnStatus() throws Exception {
        StringBuilder text = new StringBuilder("import Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "asynchronous entry main (true) {\n");
        for (int i = 0; i < 200_000; i++) {
            text.append("  .logln(\"line ").append(i).append("\");\n");
        }
        Path program = Files.writeString(folder.resolve("huge.masl"), text.append("}\n"));

        for (List<String> command : List.of(List.of("check"), List.of("run", "--no-cache"))) {
            List<String> arguments = new ArrayList<>(command);
            arguments.addAll(List.of(program.toString(), "--quiet"));
            try (MaslProcess masl = MaslProcess.startWith(List.of("-Xmx32m"), folder.resolve("journal.txt").toFile(),
                    arguments.toArray(String[]::new))) {
                assertEquals(71, masl.awaitExit(), masl::toString);
                assertTrue(masl.err().matches("masl: out of memory: the heap's \\d+ MiB is too small for this input"
                        + " \\(java -Xmx, in JAVA_OPTS or MASL_OPTS, sets it\\)\n"), masl::toString);
            }
        }
    }
}
