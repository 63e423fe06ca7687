package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Inputs that once made {@code masl} fail with an internal error (status 70) or leak a stack trace:
 * each is now a usage error, a clear one-line error, or simply works.
 */
@Timeout(120)
class NoInternalErrorTest {

    @TempDir
    Path folder;

    @Test
    void aTimeoutBeyondTheClockIsAUsageError() throws IOException {
        String program = write("ok.masl", "import Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) { .nop(); }\n");
        Run run = Run.of("run", program, "--timeout", "99999999999999999");
        assertEquals(64, run.status(), run::toString);
        assertTrue(run.err().startsWith("masl: --timeout must be at most 315360000, got 99999999999999999\n"), run::toString);
        assertEquals(64, Run.of("run", program, "--timeout", "99999999999999999999999").status());
        assertEquals(64, Run.of("run", program, "--call-timeout", "99999999999999999").status());
        assertEquals(0, Run.of("run", program, "--timeout", "315360000").status());
    }

    /** A program saved in Latin-1 is refused at its first byte that is not UTF-8, not read as some other text. */
    @Test
    void aProgramThatIsNotUtf8IsRefusedAtItsFirstBadByte() throws IOException {
        Path program = folder.resolve("latin1.masl");
        Files.write(program, ("import Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) { .logln(\"d\u00e9j\u00e0\"); }\n").getBytes(StandardCharsets.ISO_8859_1));
        String refusal = program + ":3:37: error: byte 0xE9 is not UTF-8: MASL programs are UTF-8 (save the file as UTF-8)\n";

        assertEquals(new Run(1, "", refusal), Run.of("check", program.toString()));
        assertEquals(new Run(1, "", refusal), Run.of("run", program.toString()));
    }

    @Test
    void aProgramStartingWithAByteOrderMarkRuns() throws IOException {
        Path program = folder.resolve("bom.masl");
        byte[] text = ("import Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) { .logln(\"hi\"); }\n").getBytes(StandardCharsets.UTF_8);
        byte[] withMark = new byte[text.length + 3];
        withMark[0] = (byte) 0xEF;
        withMark[1] = (byte) 0xBB;
        withMark[2] = (byte) 0xBF;
        System.arraycopy(text, 0, withMark, 3, text.length);
        Files.write(program, withMark);
        assertEquals(new Run(0, "hi\n", ""), Run.of("run", program.toString()));
        assertEquals(new Run(0, "", ""), Run.of("check", program.toString()));
    }

    @Test
    void anAgentClassWhoseStaticInitialiserThrowsIsOneLineWithItsCause() throws IOException {
        Run run = runAgent("static { if (true) { throw new IllegalStateException(\"no licence file\"); } }");
        assertEquals(1, run.status(), run::toString);
        assertEquals("masl: cannot create agent a of class bad.Bomb: its static initialiser threw"
                + " java.lang.IllegalStateException: no licence file\n", run.err());
    }

    @Test
    void anAgentWhoseConstructorThrowsIsReportedWithWhatItThrew() throws IOException {
        Run run = runAgent("public Bomb() { throw new IllegalArgumentException(\"no port /dev/robot0\"); }");
        assertEquals(1, run.status(), run::toString);
        assertEquals("masl: cannot create agent a of class bad.Bomb: its constructor threw"
                + " java.lang.IllegalArgumentException: no port /dev/robot0\n", run.err());
        assertFalse(run.err().contains("InvocationTargetException"), run::toString);
    }

    /** Runs a one-agent program whose type is {@code bad.Bomb}, a {@code Default} with {@code body}. */
    private Run runAgent(String body) throws IOException {
        Path classes = Files.createDirectories(folder.resolve("classes"));
        Path source = Files.createDirectories(folder.resolve("src/bad")).resolve("Bomb.java");
        Files.writeString(source, "package bad;\npublic class Bomb extends masl.agents.Default {\n" + body + "\n}\n");
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertEquals(0, javac.run(null, null, null, "-cp", System.getProperty("java.class.path"), "-d",
                classes.toString(), source.toString()));
        write("Bomb.xml", "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                + "<Agent short_class_name=\"Bomb\" full_class_name=\"bad.Bomb\" target_language=\"java\"/>\n");
        String program = write("bomb.masl", "import Bomb.xml as Bomb;\nBomb a = newAgent(Bomb);\n"
                + "scalar entry main (true) { .nop(); }\n");
        return Run.of("run", program, "--agent-path", classes.toString());
    }

    private String write(String name, String text) throws IOException {
        Path file = folder.resolve(name);
        Files.writeString(file, text);
        return file.toString();
    }
}
