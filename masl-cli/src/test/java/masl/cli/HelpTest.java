package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** What the command says about itself: the help of one command, of all, and the line after a mistake. */
class HelpTest {

    private static final List<String> COMMANDS = List.of("run", "container", "compile", "check", "timeline", "lsp");

    @ParameterizedTest
    @ValueSource(strings = {"run", "container", "compile", "check", "timeline", "lsp"})
    void aCommandsHelpIsItsOwnAndDescribesEveryOptionItAccepts(String command) {
        Run asked = Run.of(command, "--help");
        assertEquals(0, asked.status(), asked::toString);
        assertEquals("", asked.err());
        assertTrue(asked.out().startsWith("usage: masl " + command + " "), asked.out());
        for (String other : COMMANDS) {
            if (!other.equals(command)) {
                assertFalse(asked.out().contains("masl " + other + " "), () -> other + " in " + asked.out());
            }
        }
        for (String option : CommandLine.optionsOf(command)) {
            assertTrue(asked.out().contains("\n  " + option + " ") || asked.out().contains(", " + option + " "),
                    () -> option + " is not described in " + asked.out());
        }
        assertEquals(asked.out(), Run.of("help", command).out());
        assertEquals(asked.out(), Run.of(command, "some.masl", "-h").out());
    }

    @Test
    void theHelpOfTheCommandListsEveryCommandAndSaysHowToAskForOne() {
        Run asked = Run.of("--help");
        assertEquals(0, asked.status());
        for (String command : COMMANDS) {
            assertTrue(asked.out().contains("\n  " + command + " "), () -> command + " is not listed in " + asked.out());
            assertTrue(asked.out().contains("masl " + command + " "), asked.out());
        }
        assertTrue(asked.out().endsWith("masl COMMAND --help (or masl help COMMAND) shows the help of that command alone\n"),
                asked.out());
        assertEquals(asked.out(), Run.of("help").out());
    }

    @Test
    void anUnknownOptionGetsTheNearestOptionOfTheCommandAndItsOneLineUsage() {
        Run run = Run.of("run", "mission.masl", "--seeed", "3");
        assertEquals(64, run.status());
        assertEquals("", run.out());
        assertEquals("masl: unknown option --seeed for masl run; did you mean --seed?\n"
                + "usage: masl run FILE [OPTION]... | masl run --sim SCENARIO [OPTION]... (masl run --help for more)\n",
                run.err());
        assertEquals("masl: unknown option --agentpath for masl check; did you mean --agent-path?\n"
                + "usage: masl check FILE [--agent-path PATH] [--quiet] [--no-cache] (masl check --help for more)\n",
                Run.of("check", "--agentpath", "x", "p.masl").err());
    }

    @Test
    void anOptionOfAnotherCommandSaysWhoseItIs() {
        Run run = Run.of("check", "p.masl", "--timeout", "3");
        assertEquals(64, run.status());
        assertEquals("masl: unknown option --timeout for masl check (it is an option of masl container, masl run)\n"
                + "usage: masl check FILE [--agent-path PATH] [--quiet] [--no-cache] (masl check --help for more)\n", run.err());
    }

    @Test
    void anUnknownCommandGetsTheNearestCommandAndTheListOfCommands() {
        String usage = "usage: masl COMMAND [ARGUMENT]... (commands: run, container, compile, check, timeline, lsp;"
                + " masl --help describes them)\n";
        Run run = Run.of("rnu", "mission.masl");
        assertEquals(64, run.status());
        assertEquals("masl: unknown command 'rnu'; did you mean run?\n" + usage, run.err());
        assertEquals("masl: unknown command 'fly'\n" + usage, Run.of("fly", "--help").err());
        assertEquals("masl: unknown command 'chek'; did you mean check?\n" + usage, Run.of("help", "chek").err());
    }

    @Test
    void anyOtherMistakeOnTheCommandLineIsOneLineAndTheUsageOfItsCommand() {
        Run run = Run.of("run", "mission.masl", "--timeout", "soon");
        assertEquals(64, run.status());
        assertEquals("masl: --timeout needs a whole number, got 'soon'\n"
                + "usage: masl run FILE [OPTION]... | masl run --sim SCENARIO [OPTION]... (masl run --help for more)\n",
                run.err());
    }
}
