package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.StringJoiner;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.scheduling.SeededScheduler;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Programs of any size compile (a block of 3,000 statements was javac's "code too large",
 * an internal error): the state machine, the class initialiser of the static structure and
 * {@code reactionPc} are split between methods and classes, and the program still runs as written.
 */
@Tag("slow")
class LargeProgramTest {

    private static final int STATEMENTS = 3_000;
    private static final int DECLARATIONS = 2_000;
    private static final int EVENTS = 1_200;

    /**
     * 3,000 statements in a loop that runs twice, so jumps cross the parts of the machine both ways;
     * 2,000 declarations with no resumption point among them; 1,200 events and reactions, so the
     * static structure needs more than one class.
     */
    @Test
    @Timeout(120)
    void aBlockOfThousandsOfStatementsCompilesAndRunsInOrder() {
        StringBuilder program = new StringBuilder("import Default.xml as Default;\nDefault a = newAgent(Default);\n"
                + "scalar entry main (true) {\n");
        for (int i = 0; i < EVENTS; i++) {
            program.append("  shared event e").append(i).append(";\n");
        }
        for (int i = 0; i < DECLARATIONS; i++) {
            program.append("  local int v").append(i).append(" = ").append(i).append(";\n");
        }
        program.append("  local int round = 0;\n  emit(e").append(EVENTS - 1).append(");\n");
        program.append("  while (round < 2) {\n");
        for (int i = 0; i < STATEMENTS; i++) {
            program.append("    .logln(\"s").append(i).append(" \" + round);\n");
        }
        program.append("    round++;\n  }\n  .logln(v").append(DECLARATIONS - 1).append(");\n");
        for (int i = 0; i < EVENTS; i++) {
            program.append("  react (e").append(i).append(") { .logln(\"r").append(i).append("\"); resume; }\n");
        }
        program.append("}\n");

        Translation translation = Programs.translate("large.masl", program.toString());
        assertTrue(translation.succeeded(), () -> translation.diagnostics().sorted().toString());
        String code = translation.javaSources().get("masl.generated.large.DefaultProgram");
        assertTrue(code.contains("private final class From"), "the machine is split");
        assertTrue(code.contains("private int reactionPcFrom1000(Reaction reaction)"), "reactionPc is split");
        assertTrue(translation.javaSources().get("masl.generated.large.LargeMission")
                .contains("static final class Structure2"), "the static structure is split");

        StringJoiner expected = new StringJoiner("\n", "", "\n");
        expected.add("r" + (EVENTS - 1));
        for (int round = 0; round < 2; round++) {
            for (int i = 0; i < STATEMENTS; i++) {
                expected.add("s" + i + " " + round);
            }
        }
        expected.add(String.valueOf(DECLARATIONS - 1));
        assertEquals(expected.toString(), Programs.journal(MissionLoader.load(translation, AgentPath.parse("")),
                new SeededScheduler(1)));
    }

    @Test
    void aSmallProgramIsOneResumeMethod() {
        Translation translation = Programs.translate("small.masl", """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                scalar entry main (true) { .logln("hello"); }
                """);
        String code = translation.javaSources().get("masl.generated.small.DefaultProgram");
        assertTrue(code.contains("    protected void resume(AgentContext ctx) {\n        while (true) {\n"), code);
        assertFalse(code.contains("class From"), code);
        assertFalse(translation.javaSources().get("masl.generated.small.SmallMission").contains("Structure2"));
    }
}
