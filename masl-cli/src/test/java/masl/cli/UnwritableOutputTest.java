package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An output that cannot be written is an I/O failure, not a mistake in the command: its own status
 * (74) and one line naming the path and why, without the command's usage.
 */
class UnwritableOutputTest {

    @TempDir
    Path folder;

    @Test
    void javaSourcesUnderAFileAreAnIoFailureNamingThePath() throws IOException {
        Path program = Files.writeString(folder.resolve("one.masl"), """
                import Default.xml as Default;
                Default a = newAgent(Default);
                scalar entry main (true) { .logln("hi"); }
                """);
        Path taken = Files.writeString(folder.resolve("taken"), "a file, not a folder");

        Run run = Run.of("compile", program.toString(), "-d", taken.resolve("src").toString());

        assertEquals(74, run.status(), run.err());
        assertEquals(1, run.err().lines().count(), run.err());
        assertEquals("masl: cannot write the Java source " + taken.resolve("src") + "/", run.err().substring(0,
                ("masl: cannot write the Java source " + taken.resolve("src") + "/").length()), run.err());
    }

    @Test
    void aPageInAFolderThatDoesNotExistIsAnIoFailureNamingThePath() throws IOException {
        Path trace = Files.writeString(folder.resolve("t.jsonl"), "{\"nanos\":1,\"event\":\"mission-started\",\"agents\":[\"a\"]}\n"
                + "{\"nanos\":2,\"event\":\"mission-ended\",\"status\":\"completed\"}\n");
        Path page = folder.resolve("missing").resolve("page.html");

        Run run = Run.of("timeline", trace.toString(), "-o", page.toString());

        assertEquals(new Run(74, "", "masl: cannot write the page " + page + ": cannot create " + page + "\n"), run);
    }
}
