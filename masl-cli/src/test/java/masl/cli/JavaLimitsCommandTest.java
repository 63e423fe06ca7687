package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
 * Programs at the edges of what Java holds end with the statuses a user expects: 0 when
 * they simply work, 1 with a positioned error when Java cannot hold them; never 70, the internal
 * error each of them was.
 */
@Timeout(90)
@Tag("slow")
class JavaLimitsCommandTest {

    private static final String HEADER = "import Default.xml as Default;\nDefault a = newAgent(Default);\n";

    @TempDir
    Path folder;

    @Test
    void aBlockOfThreeThousandStatementsRuns() throws IOException {
        String statements = IntStream.range(0, 3_000).mapToObj(i -> "  .logln(\"s" + i + "\");\n")
                .collect(Collectors.joining());
        CheckCommandTest.Run run = CheckCommandTest.Run.of("run",
                write("long.masl", HEADER + "scalar entry main (true) {\n" + statements + "}\n"));
        assertEquals(0, run.status(), run.err());
        assertTrue(run.out().startsWith("s0\ns1\n") && run.out().endsWith("s2999\n"), run.out());
    }

    /** More constants than one class file holds, in one block: the parts of the program class hold them. */
    @Test
    @Timeout(600)
    void seventyThousandDistinctConstantsInOneBlockRun() throws IOException {
        String statements = IntStream.range(0, 70_000).mapToObj(i -> "  x = x + " + (100_000 + i) + ";\n")
                .collect(Collectors.joining());
        CheckCommandTest.Run run = CheckCommandTest.Run.of("run",
                write("constants.masl", HEADER + "scalar entry main (true) {\n  local int x = 0;\n" + statements + "  .logln(x);\n}\n"));
        int sum = IntStream.range(0, 70_000).map(i -> 100_000 + i).sum();
        assertEquals(new CheckCommandTest.Run(0, sum + "\n", ""), run);
    }

    @Test
    void twoThousandNestedBracketsRun() throws IOException {
        CheckCommandTest.Run run = CheckCommandTest.Run.of("run", write("deep.masl", HEADER
                + "scalar entry main (true) {\n  .logln(" + "(".repeat(2_000) + "7" + ")".repeat(2_000) + ");\n}\n"));
        assertEquals(new CheckCommandTest.Run(0, "7\n", ""), run);
    }

    @Test
    void aTypeDeclaredAsAgentRuns() throws IOException {
        CheckCommandTest.Run run = CheckCommandTest.Run.of("run", write("agent.masl",
                "type Agent use Default.xml;\nAgent a = newAgent(Agent);\nscalar entry main (true) { .logln(1); }\n"));
        assertEquals(new CheckCommandTest.Run(0, "1\n", ""), run);
    }

    @Test
    void anIntegerTooLargeIsAPositionedErrorWithStatusOne() throws IOException {
        String program = write("large.masl", HEADER + "scalar entry main (true) {\n  local int x = 2147483648;\n}\n");
        CheckCommandTest.Run check = CheckCommandTest.Run.of("check", program);
        assertEquals(1, check.status(), check.err());
        assertTrue(check.err().startsWith(program + ":4:17: error: integer number too large for an int"), check.err());
        assertEquals(1, CheckCommandTest.Run.of("run", program).status());
    }

    private String write(String name, String text) throws IOException {
        Path file = folder.resolve(name);
        Files.writeString(file, text);
        return file.toString();
    }
}
