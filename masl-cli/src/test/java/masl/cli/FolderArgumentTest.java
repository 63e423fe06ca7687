package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A folder given where a file is read is called a folder: "no such file" would send the user looking for it. */
class FolderArgumentTest {

    @TempDir
    Path folder;

    @Test
    void aFolderGivenAsTheTraceIsNamedAFolder() throws IOException {
        Path traces = Files.createDirectories(folder.resolve("traces"));

        Run run = Run.of("timeline", traces.toString(), "-o", folder.resolve("page.html").toString());

        assertEquals(64, run.status());
        assertTrue(run.err().startsWith("masl: " + traces + ": is a folder, not a trace (give the file run --trace wrote)\n"),
                run.err());
    }

    @Test
    void aFolderGivenAsTheProgramIsNamedAFolder() throws IOException {
        Path programs = Files.createDirectories(folder.resolve("programs"));

        Run run = Run.of("check", programs.toString());

        assertEquals(64, run.status());
        assertTrue(run.err().startsWith("masl: " + programs + ": is a folder, not a MASL program\n"), run.err());
    }
}
