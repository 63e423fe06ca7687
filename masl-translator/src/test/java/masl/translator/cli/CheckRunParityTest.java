package masl.translator.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import masl.translator.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * One front end, one set of diagnostics (issue 20, item 4): {@code masl check} reports every error
 * {@code masl run} and {@code masl compile} would, constructs the translator refuses included, with
 * the same text and status; and what {@code check} accepts, {@code run} runs.
 */
@Timeout(300)
class CheckRunParityTest {

    /** Two agents, one of a subtype with a primitive ({@code explore}) the other lacks; line 10 is the statement. */
    private static final String HEADER = """
            import robots/Khepera.xml;
            import robots/Explorer.xml;
            Khepera k = newAgent(Khepera);
            Khepera e = newAgent(Explorer);
            asynchronous entry main (true) {
                local Object o = new java.util.ArrayList();
                local int n = 0;
                local int f = e.survey();
                shared int limitedTo limited(Explorer) = 0;
            """;

    @TempDir
    Path folder;

    /** Each kind of construct the translator still refuses (its README, "Not translated yet"), at 10:column. */
    static Stream<Arguments> refusals() {
        return Stream.of(
                refusal("if (.getProximity(1) > 0 && k.getProximity(1) > 0) .nop();", 29,
                        "waiting for a result (an invocation of another agent, a future) in the right operand of &&,"),
                refusal("n = .getProximity(1) > 0 ? k.getProximity(1) : 0;", 5,
                        "waiting for a result (an invocation of another agent, a future) in a branch of ?:,"),
                refusal("n = (e.battery = 3) + 1;", 6, "an assignment to an attribute inside an expression"),
                refusal("n += (limitedTo = 2);", 7, "a write to a limited variable inside an expression"),
                refusal("f += 1;", 1, "a compound assignment to a variable holding a future"),
                refusal("f++;", 1, "an increment of a variable holding a future"),
                refusal("o.size = 1;", 1, "an assignment to a field of an Object-typed value"),
                refusal("if (java.nio.file.Files.size(java.nio.file.Path.of(\"x\")) > 0) .nop();", 5,
                        "a Java call that may throw a checked exception, in a condition,"),
                refusal("local long z = java.nio.file.Files.size(java.nio.file.Path.of(\"x\"));", 16,
                        "a Java call that may throw a checked exception, in an initialiser,"),
                refusal("n = Khepera.battery;", 5, "a static attribute read through its type, unless a constant,"),
                refusal("Khepera.battery = 1;", 1, "a write of a static attribute through its type"),
                refusal("n = Khepera.getProximity(1);", 5, "an invocation of a primitive through its type"));
    }

    private static Arguments refusal(String statement, int column, String construct) {
        return Arguments.of(statement, 10 + ":" + column + ": error: " + construct + " is not supported yet by the translator");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("refusals")
    void checkCompileAndRunReportARefusalAlike(String statement, String diagnostic) throws IOException {
        String program = write("refused.masl", HEADER + statement + "\n}\n");
        Run check = Run.of("check", program, "--agent-path", fixtures());
        assertEquals(1, check.status(), check.err());
        assertTrue(check.err().startsWith(program + ":" + diagnostic + "\n"), check.err());
        assertTrue(check.err().endsWith("\n1 error\n"), check.err());
        assertEquals(check, Run.of("run", program, "--agent-path", fixtures()));
        Path java = folder.resolve("java");
        assertEquals(check, Run.of("compile", program, "-d", java.toString(), "--agent-path", fixtures()));
        assertFalse(Files.exists(java), "compile wrote sources for a program with errors");
    }

    /** MASL §4, §10: the label's invocation is a nop() for the Khepera, which lacks explore; check accepts it. */
    @Test
    void aLabelOverAPrimitiveOneTypeLacksIsAcceptedByCheckAndRuns() throws IOException {
        String program = write("label.masl", """
                import robots/Khepera.xml;
                import robots/Explorer.xml;
                Khepera k = newAgent(Khepera);
                Khepera e = newAgent(Explorer);
                asynchronous entry main (true) {
                    LLabel l;
                    local String found = "nothing";
                    l.found = e.explore("north");
                    l.explore("south");
                    l.k.explore("east");
                    while (!l.isFinished()) {}
                    .logln(.getProxyID() + " found " + found);
                }
                """);
        assertEquals(new Run(0, "", ""), Run.of("check", program, "--agent-path", fixtures()));
        Run run = Run.of("run", program, "--agent-path", fixtures());
        assertEquals(0, run.status(), run.err());
        assertEquals(Stream.of("0 found north", "1 found north").sorted().toList(), run.out().lines().sorted().toList());
    }

    private String write(String name, String text) throws IOException {
        Path file = folder.resolve(name);
        Files.writeString(file, text);
        return file.toString();
    }

    /** The folder the fixture descriptors ({@code robots/Khepera.xml}) are found from. */
    private static String fixtures() {
        try {
            return Path.of(CheckRunParityTest.class.getResource("/analysis/robots/Khepera.xml").toURI()).getParent()
                    .getParent().toString();
        } catch (URISyntaxException impossible) {
            throw new IllegalStateException(impossible);
        }
    }
}
