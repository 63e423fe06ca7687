package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import masl.e2e.ManualExamples.Check;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** The checks ManualTest makes of a page fail when the page shows what the program does not do. */
@Timeout(120)
class ManualHarnessTest {

    private static final String PROGRAM = """
            ```masl
            import Default.xml as Default;
            Default a, b = newAgent(Default);
            asynchronous entry main (true) {
              .logln("agent " + .getProxyID());
            }
            ```
            """;

    @TempDir
    Path folder;

    @Test
    void aJournalInAnyOrderThatTheProgramWritesPasses() {
        verify(PROGRAM + "```journal any-order\nagent 1\nagent 0\n```\n");
    }

    @Test
    void aWrongJournalFailsAndShowsWhatTheProgramWrote() {
        AssertionError failure = assertThrows(AssertionError.class,
                () -> verify(PROGRAM + "```journal any-order\nagent 0\nagent 2\n```\n"));
        assertTrue(failure.getMessage().contains("instead of the journal shown at page.md:8"), failure::getMessage);
        assertTrue(failure.getMessage().contains("agent 1"), failure::getMessage);
    }

    @Test
    void errorsThatMaslCheckDoesNotGiveFail() {
        String broken = "```masl file=broken.masl\nimport Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) {\n  .logln(1)\n}\n```\n";
        verify(broken + "```error\nbroken.masl:4:12: error: expected ';'\n  .logln(1)\n           ^\n1 error\n```\n");
        AssertionError failure = assertThrows(AssertionError.class,
                () -> verify(broken + "```error\nbroken.masl:4:3: error: expected ';'\n1 error\n```\n"));
        assertTrue(failure.getMessage().contains("instead of the errors shown"), failure::getMessage);
    }

    @Test
    void aFailureReportThatMaslRunDoesNotGiveFails() {
        String stuck = "```masl file=stuck.masl\nimport Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "asynchronous entry main (true) {\n  shared boolean done = false;\n  while (!done) {}\n}\n```\n";
        String report = "masl: the mission deadlocked: no agent can make progress\n"
                + "agent a (0) at pc 2 (stuck.masl:5: while (!done)): [main]\n";
        verify(stuck + "```failure\n" + report + "```\n");
        AssertionError failure = assertThrows(AssertionError.class,
                () -> verify(stuck + "```failure\n" + report.replace("a (0)", "b (1)") + "```\n"));
        assertTrue(failure.getMessage().contains("instead of the report shown"), failure::getMessage);
    }

    @Test
    void aProgramThatDiffersFromTheFileItNamesFails() {
        String e1 = "src/test/resources/examples/e1_scalar_main.masl";
        AssertionError failure = assertThrows(AssertionError.class,
                () -> verify("```masl source=" + e1 + "\n" + PROGRAM.lines().skip(1).limit(5).map(line -> line + "\n")
                        .reduce("", String::concat) + "```\n```journal any-order\nagent 0\nagent 1\n```\n"));
        assertTrue(failure.getMessage().contains("differs from " + e1), failure::getMessage);
    }

    @Test
    void aProgramWithNothingUnderItFails() {
        AssertionError failure = assertThrows(AssertionError.class, () -> verify(PROGRAM));
        assertTrue(failure.getMessage().contains("no ```journal, ```error or ```failure block under it"), failure::getMessage);
    }

    @Test
    void aFragmentThatDoesNotCheckFails() {
        verify("```masl fragment\nlocal int n = 0;\nn++;\n```\n");
        AssertionError failure = assertThrows(AssertionError.class,
                () -> verify("```masl fragment\nfor (int i = 0; i < 3; i++) { .nop(); }\n```\n"));
        assertTrue(failure.getMessage().contains("does not check"), failure::getMessage);
    }

    @Test
    void aBlockWithoutALanguageFails() {
        AssertionError failure = assertThrows(AssertionError.class, () -> verify("```\nagent 0\n```\n"));
        assertTrue(failure.getMessage().contains("without a language"), failure::getMessage);
    }

    @Test
    void theFilesOfAPageAreItsAgentPath() {
        verify("""
                ```xml file=Greeter.xml
                <?xml version="1.0" encoding="UTF-8"?>
                <Agent short_class_name="Greeter" full_class_name="manual.Greeter">
                  <Primitive function_name="greeting" member_id="G1" synchronous_call="true"
                             return_type_name="java.lang.String"/>
                </Agent>
                ```
                ```java file=manual/Greeter.java
                package manual;
                public class Greeter extends masl.agents.Default {
                    public String greeting() { return "hello"; }
                }
                ```
                ```masl
                import Greeter.xml as Greeter;
                Greeter g = newAgent(Greeter);
                scalar entry main (true) { .logln(.greeting()); }
                ```
                ```journal
                hello
                ```
                """);
    }

    private void verify(String markdown) {
        List<Check> checks = ManualExamples.of(ManualPage.parse("page.md", markdown), folder.resolve("page"));
        assertEquals(false, checks.isEmpty());
        checks.forEach(check -> check.verify().run());
    }
}
