package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Large teams through {@code masl run}, in the default test JVM: they must simply complete (speed is
 * measured by {@code gradle bench}, not here).
 */
@Tag("slow")
class ScaleTest {

    @TempDir
    Path folder;

    @Test
    @Timeout(90)
    void aThousandAgentsTakeAThousandLockStepSteps() throws IOException {
        Path program = team("thousand.masl", 1000, """
                synchronous entry main (true) {
                  shared int steps = 0;
                  local int i = 0;
                  while (i < 1000) {
                    i++;
                  }
                  scalar entry count (true) { steps = i; }
                  .nop();
                  scalar entry report (main.count == 1000) { .logln("steps " + steps); }
                }
                """);
        assertEquals("steps 1000\n", run(program));
    }

    @Test
    @Timeout(90)
    void tenThousandAgentsTakeTenLockStepSteps() throws IOException {
        Path program = team("ten-thousand.masl", 10_000, """
                synchronous entry main (true) {
                  shared int arrived = 0;
                  local int i = 0;
                  while (i < 10) {
                    i++;
                  }
                  arrived++;
                  .nop();
                  scalar entry report (true) { .logln(arrived + " agents, " + i + " steps each"); }
                }
                """);
        assertEquals("10000 agents, 10 steps each\n", run(program));
    }

    /** A program of {@code size} Default agents, a0, a1, ..., running {@code blocks}. */
    private Path team(String name, int size, String blocks) throws IOException {
        String agents = IntStream.range(0, size).mapToObj(i -> "a" + i).collect(Collectors.joining(", "));
        Path program = folder.resolve(name);
        Files.writeString(program, "import Default.xml as Default;\nDefault " + agents + " = newAgent(Default);\n" + blocks);
        return program;
    }

    private static String run(Path program) {
        MaslCommand run = MaslCommand.run("run", program.toString());
        assertEquals(0, run.status(), run.err());
        return run.out();
    }
}
