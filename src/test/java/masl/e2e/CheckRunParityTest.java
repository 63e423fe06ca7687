package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * One front end, one set of diagnostics: {@code masl check} reports every error
 * {@code masl run} and {@code masl compile} would, the constructs the translator refuses included,
 * with the same text and status; and a program {@code check} accepts, {@code run} runs. The Worker
 * and Scout types of {@code src/test/resources/workers}, found on the class path.
 */
@Timeout(60)
class CheckRunParityTest {

    /** Line 11 of each program is the statement under test. */
    private static final String HEADER = """
            import workers/Worker.xml;
            import workers/Scout.xml;
            import SoftWheeledRobot.xml as Soft;
            Worker w = newAgent(Worker);
            Worker s = newAgent(Scout);
            asynchronous entry main (true) {
                local Object o = new java.util.ArrayList();
                local int n = 0;
                local int f = s.slow(1);
                shared int onlyScouts limited(Scout) = 0;
            """;
    private static final int LINE = 11;

    @TempDir
    Path folder;

    /**
     * Each kind of construct the translator still refuses (its README, "Not translated yet"): the
     * statement, the text the error points at, what the error says is not supported.
     */
    static Stream<Arguments> refusals() {
        return Stream.of(
                Arguments.of("if (.twice(1) > 0 && w.twice(1) > 0) .nop();", "w.twice(1) > 0)",
                        "waiting for a result (an invocation of another agent, a future) in the right operand of &&,"),
                Arguments.of("n = .twice(1) > 0 ? w.twice(1) : 0;", ".twice(1) > 0 ?",
                        "waiting for a result (an invocation of another agent, a future) in a branch of ?:,"),
                Arguments.of("n = (w.battery = 3) + 1;", "w.battery = 3", "an assignment to an attribute inside an expression"),
                Arguments.of("n += (onlyScouts = 2);", "onlyScouts = 2", "a write to a limited variable inside an expression"),
                Arguments.of("f += 1;", "f += 1", "a compound assignment to a variable holding a future"),
                Arguments.of("f++;", "f++", "an increment of a variable holding a future"),
                Arguments.of("o.size = 1;", "o.size", "an assignment to a field of an Object-typed value"),
                Arguments.of("if (java.nio.file.Files.size(java.nio.file.Path.of(\"x\")) > 0) .nop();", "java.nio",
                        "a Java call that may throw a checked exception, in a condition,"),
                Arguments.of("local long z = java.nio.file.Files.size(java.nio.file.Path.of(\"x\"));", "java.nio",
                        "a Java call that may throw a checked exception, in an initialiser,"),
                Arguments.of("n = Worker.made;", "Worker.made", "a static attribute read through its type, unless a constant,"),
                Arguments.of("Worker.made = 1;", "Worker.made", "a write of a static attribute through its type"),
                Arguments.of("n = Worker.MOVE_COST;", "Worker.MOVE_COST", "an attribute that the owner's declared type lacks"),
                Arguments.of("n = Worker.twice(1);", "Worker.twice", "an invocation of a primitive through its type"));
    }

    @ParameterizedTest
    @MethodSource("refusals")
    void checkCompileAndRunReportARefusalAlike(String statement, String at, String construct) throws IOException {
        String program = write("refused.masl", HEADER + "    " + statement + "\n}\n");
        int column = "    ".length() + statement.indexOf(at) + 1;
        MaslCommand check = MaslCommand.run("check", program);
        assertEquals(1, check.status(), check::toString);
        assertEquals(List.of(program + ":" + LINE + ":" + column + ": error: " + construct
                + " is not supported yet by the translator", "    " + statement, " ".repeat(column - 1) + "^", "1 error"),
                check.err().lines().toList());
        assertEquals(check, MaslCommand.run("run", program));
        Path java = folder.resolve("java");
        assertEquals(check, MaslCommand.run("compile", program, "-d", java.toString()));
        assertFalse(Files.exists(java), "compile wrote sources for a program with errors");
    }

    /** MASL §4, §10: the label's invocations are nops for the Worker, which lacks scan and sweep. */
    @Test
    void aLabelOverAPrimitiveOneTypeLacksIsAcceptedByCheckAndRuns() throws IOException {
        String program = write("label.masl", """
                import workers/Worker.xml;
                import workers/Scout.xml;
                Worker w = newAgent(Worker);
                Worker s = newAgent(Scout);
                asynchronous entry main (true) {
                    LLabel l;
                    local int found = -1;
                    l.found = s.scan();
                    l.sweep(1);
                    l.w.sweep(2);
                    while (!l.isFinished()) {}
                    .logln(.getProxyID() + " found " + found);
                }
                """);
        assertEquals(new MaslCommand(0, "", ""), MaslCommand.run("check", program));
        MaslCommand run = MaslCommand.run("run", program);
        assertEquals(0, run.status(), run::toString);
        assertEquals(List.of("0 found 7", "1 found 7", "1 sweeps 1"), run.out().lines().sorted().toList());
        assertTrue(run.err().isEmpty(), run::toString);
    }

    private String write(String name, String text) throws IOException {
        Path file = folder.resolve(name);
        Files.writeString(file, text);
        return file.toString();
    }
}
