package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A mission whose data grows for ever, in a JVM of 64 MiB: the heap's exhaustion fails the mission
 * as any failure does (status 2, where the agents were, a complete trace), never as an internal
 * error or a thread's stack trace.
 */
@Timeout(300)
@Tag("slow")
class OutOfMemoryTest {

    @TempDir
    Path folder;

    @Test
    void aProgramThatExhaustsTheHeapFailsTheMissionWithItsReportAndACompleteTrace() throws Exception {
        Path program = Files.writeString(folder.resolve("grow.masl"), """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                asynchronous entry main (true) {
                  local Vector kept = new Vector();
                  while (true) {
                    kept.add("some text that takes room " + kept.size());
                  }
                }
                """);
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
}
