package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code masl run --trace FILE [--trace-limit SIZE]}: a trace lost fails the run, a trace at its limit is cut. */
@Timeout(120)
class TraceOutputTest {

    /** 3000 turns of a block: about a megabyte of trace. */
    private static final String TICKING = ticking("Default", 3000);

    /** A program whose agent k, of {@code type}, turns a block {@code turns} times, then logs "done". */
    static String ticking(String type, int turns) {
        return """
                import %1$s.xml as %1$s;
                %1$s k = newAgent(%1$s);
                asynchronous entry main (true) {
                  local int i = 0;
                  asynchronous entry tick (i < %2$d) {
                    i++;
                    reelect;
                  }
                  .logln("done");
                }
                """.formatted(type, turns);
    }

    @TempDir
    Path folder;

    @Test
    void aTraceThatCannotBeWrittenFailsTheRun() throws IOException {
        assertTrue(new File("/dev/full").exists(), "this test needs Linux's /dev/full");
        Path program = hello();

        Run run = Run.of("run", program.toString(), "--trace", "/dev/full");

        assertEquals(2, run.status(), run.err());
        assertEquals("masl: cannot write the trace to /dev/full: No space left on device\n", run.err());
    }

    /** A trace that cannot even be opened is the same failure, in one line: not bad usage with the usage after it. */
    @Test
    void aTraceIntoAFolderFailsTheRunInOneLine() throws IOException {
        Path program = hello();
        Path traces = Files.createDirectories(folder.resolve("traces"));

        Run run = Run.of("run", program.toString(), "--trace", traces.toString());

        assertEquals(new Run(2, "", "masl: cannot write the trace to " + traces + ": it is a folder\n"), run);
    }

    @Test
    void aTraceThatFailsWhileTheMissionRunsStopsIt() throws IOException {
        Path program = Files.writeString(folder.resolve("tick.masl"), ticking("Default", Integer.MAX_VALUE));

        Run run = Run.of("run", program.toString(), "--trace", "/dev/full");

        assertEquals(2, run.status(), run.err());
        assertEquals("masl: cannot write the trace to /dev/full: No space left on device\n", run.err());
    }

    @Test
    void aTraceAtItsLimitEndsWithTheCutRecordAndTheRunGoesOn() throws IOException {
        Path program = Files.writeString(folder.resolve("tick.masl"), TICKING);
        Path trace = folder.resolve("tick.jsonl");

        Run run = Run.of("run", program.toString(), "--trace", trace.toString(), "--trace-limit", "64K");

        assertEquals(0, run.status(), run.err());
        assertEquals("done\n", run.out());
        assertEquals("masl: the trace " + trace + " was cut at its limit of 65536 bytes (--trace-limit)\n", run.err());
        assertTrue(Files.size(trace) <= 65536, Files.size(trace) + " bytes");
        List<String> lines = Files.readAllLines(trace);
        ObjectMapper json = new ObjectMapper();
        for (String line : lines) {
            json.readTree(line);
        }
        String last = lines.get(lines.size() - 1);
        assertTrue(last.matches("\\{\"nanos\":\\d+,\"event\":\"trace-cut\",\"limit\":65536}"), last);

        Path page = folder.resolve("tick.html");
        assertEquals(new Run(0, "", ""), Run.of("timeline", trace.toString(), "-o", page.toString()));
        assertTrue(Files.readString(page).contains("trace cut at its limit of 65536 bytes"));
    }

    @Test
    void aLimitIsASizeOfAtLeastAKilobyte() throws IOException {
        Path program = Files.writeString(folder.resolve("tick.masl"), TICKING);

        Run small = Run.of("run", program.toString(), "--trace-limit", "1000");
        Run word = Run.of("run", program.toString(), "--trace-limit", "lots");

        assertEquals(64, small.status());
        assertTrue(small.err().startsWith("masl: --trace-limit must be at least 1024 bytes, got 1000\n"), small.err());
        assertEquals(64, word.status());
        assertTrue(word.err().startsWith("masl: --trace-limit needs a size in bytes, such as 1048576, 64K, 512M or 1G,"
                + " got 'lots'\n"), word.err());
    }

    @Test
    void aLimitWithoutATraceToCutIsBadUsageNotIgnored() throws IOException {
        Path program = Files.writeString(folder.resolve("tick.masl"), TICKING);

        Run run = Run.of("run", program.toString(), "--trace-limit", "64K");

        assertEquals(64, run.status());
        assertTrue(run.err().startsWith("masl: --trace-limit cuts the trace of --trace FILE"), run.err());
        assertEquals("", run.out(), "the mission did not run");
    }

    /** A program that logs "hi". */
    private Path hello() throws IOException {
        return Files.writeString(folder.resolve("hello.masl"), """
                import Default.xml as Default;
                Default a = newAgent(Default);
                scalar entry main (true) { .logln("hi"); }
                """);
    }
}
