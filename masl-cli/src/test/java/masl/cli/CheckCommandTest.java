package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** {@code masl check} as a user meets it: exit statuses, the rendering of errors, usage mistakes. */
class CheckCommandTest {

    @TempDir
    Path folder;

    /** One run of the command, with what it printed. */
    record Run(int status, String out, String err) {
        /** A run without progress lines: standard error holds the diagnostics alone, however slow the machine. */
        static Run of(String... args) {
            return with(Progress.Settings.standard().quiet(true), args);
        }

        /** A run whose progress lines follow {@code progress} (its clock, its terminal or not). */
        static Run with(Progress.Settings progress, String... args) {
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            int status = new Masl(System.in, new PrintStream(out, true, StandardCharsets.UTF_8),
                    new PrintStream(err, true, StandardCharsets.UTF_8), progress).run(args);
            return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
        }
    }

    private Path write(String name, String text) throws IOException {
        Path file = folder.resolve(name);
        Files.writeString(file, text);
        return file;
    }

    @Test
    void aCorrectProgramGivesSilenceAndStatusZero() throws IOException {
        Path program = write("hello.masl", """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                scalar entry main (true) { .logln("hi"); }
                """);
        assertEquals(new Run(0, "", ""), Run.of("check", program.toString()));
    }

    @Test
    void anErrorIsPrintedWithItsPositionSourceLineAndCaret() throws IOException {
        Path program = write("broken.masl", """
                import Default.xml as Default;
                Default a = newAgent(Default);
                scalar entry main (true {
                  .logln("hi");
                }
                """);
        Run run = Run.of("check", program.toString());
        assertEquals(1, run.status());
        assertEquals(program + ":3:24: error: expected ')'\n"
                + "scalar entry main (true {\n"
                + "                       ^\n"
                + "1 error\n", run.err());
        assertEquals("", run.out());
    }

    /** The top-level README's example: syntax and other errors of a file, all in one run, each once. */
    @Test
    void everyErrorOfTheFileInOneRun() throws IOException {
        Path program = write("broken.masl", """
                import Default.xml as Default;
                Default alice, bob, carol = newAgent(Default);
                scalar entry main (true) {
                    String greeting = "Hello from agent ";
                    .log(greeting)
                    .logln(.getProxyID();
                    whle (.getProxyID() > 0) {
                        .logln(greting);
                    }
                }
                """);
        Run run = Run.of("check", program.toString());
        assertEquals(1, run.status());
        assertEquals(program + ":4:5: error: a declaration needs `local` or `shared` and goes at the head of its"
                + " block: `local String greeting …;`\n"
                + "    String greeting = \"Hello from agent \";\n"
                + "    ^\n"
                + program + ":5:19: error: expected ';'\n"
                + "    .log(greeting)\n"
                + "                  ^\n"
                + program + ":6:25: error: expected ')'\n"
                + "    .logln(.getProxyID();\n"
                + "                        ^\n"
                + program + ":7:5: error: unknown keyword whle; did you mean `while`?\n"
                + "    whle (.getProxyID() > 0) {\n"
                + "    ^\n"
                + program + ":8:16: error: cannot find symbol greting; did you mean `greeting`?\n"
                + "        .logln(greting);\n"
                + "               ^\n"
                + "5 errors\n", run.err());
    }

    @Test
    void aMissingFileIsBadUsage() {
        Run run = Run.of("check", folder.resolve("absent.masl").toString());
        assertEquals(64, run.status());
        assertTrue(run.err().contains("absent.masl: no such file"), run.err());
    }

    @Test
    void noCommandUnknownCommandAndUnknownOptionAreBadUsage() throws IOException {
        Path program = write("p.masl", "import Default.xml;\n");
        assertEquals(64, Run.of().status());
        assertEquals(64, Run.of("chek", program.toString()).status());
        assertEquals(64, Run.of("check", "--fast", program.toString()).status());
        assertEquals(64, Run.of("check", program.toString(), program.toString()).status());
        assertEquals(64, Run.of("check", program.toString(), "--agent-path").status());
    }

    @ParameterizedTest
    @ValueSource(strings = {"run", "check", "compile", "container", "timeline"})
    void everyCommandAnswersHelpWithItsUsageAndStatusZero(String command) {
        for (String help : List.of("--help", "-h")) {
            Run run = Run.of(command, help);
            assertEquals(0, run.status(), run::toString);
            assertTrue(run.out().startsWith("usage: masl ") && run.out().contains("masl " + command), run.out());
            assertEquals("", run.err());
        }
        Run asked = Run.of("help", command);
        assertEquals(0, asked.status());
        assertTrue(asked.out().startsWith("usage: masl "), asked.out());
    }

    @Test
    void helpPrintsTheUsageOnStandardOutput() {
        Run run = Run.of("--help");
        assertEquals(0, run.status());
        assertTrue(run.out().startsWith("usage: masl ") && run.out().contains("masl check FILE"), run.out());
    }
}
