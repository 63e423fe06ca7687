package masl.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * No output of a command writes over one of its inputs, whatever the name it is given by: the same
 * name, a symbolic link, a hard link. The command says which output is which input, exits 64 and
 * writes nothing.
 */
@Timeout(120)
class OutputOverInputTest {

    private static final String PROGRAM = """
            import Default.xml as Default;
            Default a = newAgent(Default);
            scalar entry main (true) { .logln("hi"); }
            """;

    @TempDir
    Path folder;

    private Path program() throws IOException {
        return Files.writeString(folder.resolve("victim.masl"), PROGRAM);
    }

    @Test
    void aTraceNamedAsTheProgramIsRefusedAndTheProgramKept() throws IOException {
        Path program = program();
        Run run = Run.of("run", program.toString(), "--trace", program.toString());

        assertEquals(64, run.status(), run.err());
        assertTrue(run.err().startsWith("masl: the trace " + program + " is the program " + program
                + ": masl does not write over a file it reads\n"), run.err());
        assertEquals("", run.out(), "the mission did not run");
        assertEquals(PROGRAM, Files.readString(program));
    }

    @Test
    void aTraceThatIsALinkToTheProgramIsTheProgram() throws IOException {
        Path program = program();
        Path symbolic = Files.createSymbolicLink(folder.resolve("symbolic.jsonl"), program);
        Path hard = Files.createLink(folder.resolve("hard.jsonl"), program);
        for (Path link : new Path[] {symbolic, hard}) {
            Run run = Run.of("run", program.toString(), "--trace", link.toString());

            assertEquals(64, run.status(), run.err());
            assertTrue(run.err().startsWith("masl: the trace " + link + " is the program " + program
                    + " (the same file): masl does not write over a file it reads\n"), run.err());
        }
        assertEquals(PROGRAM, Files.readString(program));
    }

    @Test
    void aTraceOverADescriptorOrAFileOfTheAgentPathIsRefused() throws IOException {
        Path program = program();
        Path descriptor = Files.writeString(folder.resolve("Robot.xml"), "<agent/>");
        Path library = Files.createDirectories(folder.resolve("lib"));
        Path agentClass = Files.write(library.resolve("Robot.class"), new byte[] {(byte) 0xca, (byte) 0xfe});

        Run overDescriptor = Run.of("run", program.toString(), "--trace", descriptor.toString());
        Run overAgentPath = Run.of("run", program.toString(), "--agent-path", library.toString(),
                "--trace", agentClass.toString());

        assertEquals(64, overDescriptor.status(), overDescriptor.err());
        assertTrue(overDescriptor.err().contains("is the descriptor " + descriptor), overDescriptor.err());
        assertEquals(64, overAgentPath.status(), overAgentPath.err());
        assertTrue(overAgentPath.err().contains("is the agent path's file " + agentClass), overAgentPath.err());
        assertEquals("<agent/>", Files.readString(descriptor));
        assertArrayEquals(new byte[] {(byte) 0xca, (byte) 0xfe}, Files.readAllBytes(agentClass));
    }

    @Test
    void aTimelinePageNamedAsItsTraceIsRefusedAndTheTraceKept() throws IOException {
        Path trace = folder.resolve("tr.jsonl");
        assertEquals(0, Run.of("run", program().toString(), "--trace", trace.toString()).status());
        byte[] written = Files.readAllBytes(trace);

        Run run = Run.of("timeline", trace.toString(), "-o", trace.toString());

        assertEquals(64, run.status(), run.err());
        assertTrue(run.err().startsWith("masl: the page " + trace + " is the trace " + trace), run.err());
        assertArrayEquals(written, Files.readAllBytes(trace));
    }

    @Test
    void compileWritesNoSourceOverAnInputAndNoSourceAtAll() throws IOException {
        Path program = program();
        Path first = folder.resolve("first");
        assertEquals(0, Run.of("compile", program.toString(), "-d", first.toString()).status());
        Path second = folder.resolve("second");
        Path linked = null;
        try (Stream<Path> sources = Files.walk(first)) {
            for (Path source : sources.filter(Files::isRegularFile).toList()) {
                Path target = second.resolve(first.relativize(source));
                Files.createDirectories(target.getParent());
                if (linked == null) {
                    linked = Files.createSymbolicLink(target, program);
                }
            }
        }

        Run run = Run.of("compile", program.toString(), "-d", second.toString());

        assertEquals(64, run.status(), run.err());
        assertTrue(run.err().startsWith("masl: the Java source " + linked + " is the program " + program), run.err());
        assertEquals(PROGRAM, Files.readString(program));
        try (Stream<Path> written = Files.walk(second)) {
            assertEquals(1, written.filter(file -> Files.isRegularFile(file) || Files.isSymbolicLink(file)).count(),
                    "nothing written beside the link");
        }
    }

    @Test
    void aSimulationWritesNoOutputOverItsScenarioOrMission() throws IOException {
        Path mission = program();
        Files.writeString(folder.resolve("floor.xode"), """
                <xode version="1.0r23"><world><space>
                  <geom name="floor"><plane a="0" b="0" c="1" d="0"/></geom>
                </space></world></xode>""");
        Path scenario = Files.writeString(folder.resolve("s.scenario.xml"), """
                <scenario name="s">
                  <world file="floor.xode"/>
                  <mission file="victim.masl"/>
                </scenario>""");
        Path out = Files.createDirectories(folder.resolve("out"));
        Path journal = Files.createLink(out.resolve("journal.txt"), mission);
        Path trace = Files.createSymbolicLink(out.resolve("trace.jsonl"), folder.resolve("floor.xode"));

        Run run = Run.of("run", "--sim", scenario.toString(), "--out", out.toString());

        assertEquals(64, run.status(), run.err());
        assertTrue(run.err().contains(" is the program " + mission + " (the same file)")
                || run.err().contains(" is the world " + folder.resolve("floor.xode")), run.err());
        assertEquals(PROGRAM, Files.readString(journal));
        assertFalse(Files.readString(trace).isEmpty());
        try (Stream<Path> written = Files.list(out)) {
            assertEquals(2, written.count(), "nothing written beside the links");
        }
    }
}
