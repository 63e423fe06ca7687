package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code masl run} and {@code masl compile}: output streams and exit statuses. */
@Timeout(120)
class RunCommandTest {

    private static final String HEADER = "import Default.xml as Default;\nDefault a, b = newAgent(Default);\n";

    @TempDir
    Path folder;

    private String write(String name, String text) throws IOException {
        Path file = folder.resolve(name);
        Files.writeString(file, text);
        return file.toString();
    }

    @Test
    void theJournalAndOnlyTheJournalGoesToStandardOutput() throws IOException {
        String program = write("two.masl", HEADER + """
                synchronous entry main (true) {
                  .log("x");
                  scalar entry end (true) { .logln(""); }
                }
                """);
        assertEquals(new Run(0, "xx\n", ""), Run.of("run", program));
        assertEquals(new Run(0, "xx\n", ""), Run.of("run", program, "--threads"));
        assertEquals(new Run(0, "xx\n", ""), Run.of("run", "--seed", "42", program));
    }

    @Test
    void errorsInTheProgramExitWithOneAndPrintNothingOnStandardOutput() throws IOException {
        Run run = Run.of("run", write("bad.masl", HEADER + "scalar entry main (true) { .fly(); }\n"));
        assertEquals(1, run.status());
        assertEquals("", run.out());
        assertTrue(run.err().contains("bad.masl:3:29: error: cannot find primitive fly"), run.err());
    }

    @Test
    void aConstructNotTranslatedYetIsAPositionedErrorWithStatusOne() throws IOException {
        Run run = Run.of("run", write("closed.masl", HEADER + """
                asynchronous entry main (true) {
                  .nop();
                  .logln("" + (.getProxyID() > 0 || a.getProxyID() > 0));
                }
                """));
        assertEquals(1, run.status());
        assertTrue(run.err().contains("closed.masl:5:37: error: waiting for a result (an invocation of another agent,"
                + " a future) in the right operand of ||, is not supported yet by the translator"), run.err());
    }

    @Test
    void aDeadlockExitsWithTwoAndReportsWhereEachAgentIs() throws IOException {
        Run run = Run.of("run", write("stuck.masl", HEADER + """
                asynchronous entry main (true) {
                  shared int go = 0;
                  while (go == 0) {}
                }
                """));
        assertEquals(2, run.status());
        assertEquals("", run.out());
        assertTrue(run.err().startsWith("masl: the mission deadlocked"), run.err());
        assertTrue(run.err().contains("agent a (0) at pc 2 (stuck.masl:5: while (go == 0))"), run.err());
        assertTrue(run.err().contains("agent b (1) at pc 2 (stuck.masl:5: while (go == 0))"), run.err());
        assertFalse(run.err().contains("\tat "), run.err());
    }

    @Test
    void aTimeoutExitsWithTwo() throws IOException {
        Run run = Run.of("run", "--timeout", "1", write("forever.masl", HEADER + """
                asynchronous entry main (true) {
                  local int i = 0;
                  while (true) { i = i + 1; }
                }
                """));
        assertEquals(2, run.status());
        assertTrue(run.err().startsWith("masl: the mission timed out"), run.err());
    }

    @Test
    void aProgramThatThrowsFailsTheMissionWithTwoAndNoStackTrace() throws IOException {
        String program = write("crash.masl", HEADER + """
                asynchronous entry main (true) {
                  .logln(10 / (.getProxyID() - .getProxyID()));
                }
                """);
        Run run = Run.of("run", "--seed", "7", program, "--call-timeout", "500");
        assertEquals(2, run.status());
        assertTrue(run.err().startsWith("masl: the mission failed"), run.err());
        assertTrue(run.err().contains("ArithmeticException"), run.err());
        assertTrue(run.err().contains("(crash.masl:4: .logln(10 / (.getProxyID() - .getProxyID()));) failed"),
                run.err());
        assertTrue(run.err().endsWith("masl: the same run again: masl run " + program + " --call-timeout 500 --seed 7\n"),
                run.err());
        assertFalse(run.err().contains("\tat "), run.err());
    }

    @Test
    void badUsageExitsWithSixtyFour() throws IOException {
        String program = write("ok.masl", HEADER + "scalar entry main (true) { .nop(); }\n");
        assertEquals(64, Run.of("run", program, "--fast").status());
        assertEquals(64, Run.of("run", program, "--seed", "x").status());
        assertEquals(64, Run.of("run", program, "--timeout", "0").status());
        assertEquals(64, Run.of("run", program, "--threads", "--seed", "1").status());
        assertEquals(64, Run.of("run", folder.resolve("missing.masl").toString()).status());
        assertEquals(64, Run.of("compile", program).status());
        assertEquals(64, Run.of("check", program, "--threads").status());
    }

    @Test
    void anOutputFolderWithoutTheSimulatorIsBadUsageNotIgnored() throws IOException {
        String program = write("ok.masl", HEADER + "scalar entry main (true) { .logln(1); }\n");
        Run run = Run.of("run", program, "--out", folder.resolve("out").toString());
        assertEquals(64, run.status());
        assertTrue(run.err().contains("--out is where --sim writes a simulation's outputs"), run.err());
        assertEquals("", run.out(), "the mission did not run");
        assertFalse(Files.exists(folder.resolve("out")));
    }

    @Test
    void theTraceIsWrittenAsJsonLines() throws IOException {
        Path trace = folder.resolve("trace.jsonl");
        String program = write("traced.masl", HEADER + "synchronous entry main (true) { .nop(); }\n");
        assertEquals(0, Run.of("run", program, "--trace", trace.toString()).status());
        List<String> lines = Files.readAllLines(trace);
        assertFalse(lines.isEmpty());
        assertTrue(lines.stream().allMatch(line -> line.startsWith("{") && line.endsWith("}")), lines.toString());
    }

    @Test
    void compileWritesTheSourcesInPackageFolders() throws IOException {
        String program = write("hello.masl", HEADER + "scalar entry main (true) { .logln(\"hi\"); }\n");
        Path out = folder.resolve("generated");
        assertEquals(new Run(0, "", ""), Run.of("compile", program, "-d", out.toString()));
        Path mission = out.resolve("masl/generated/hello/HelloMission.java");
        assertTrue(Files.readString(mission).startsWith("package masl.generated.hello;"));
        try (Stream<Path> files = Files.list(mission.getParent())) {
            assertEquals(List.of("DefaultProgram.java", "HelloMission.java"),
                    files.map(file -> file.getFileName().toString()).sorted().toList());
        }
    }
}
