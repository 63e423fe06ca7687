package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** {@code masl run} on the project's own missions, as the README shows it. */
@Timeout(120)
class CommandLineTest {

    @Test
    void helloPrintsOneGreetingFromOneOfItsThreeAgents() {
        MaslCommand run = MaslCommand.run("run", "missions/hello.masl");
        assertEquals(0, run.status(), run.err());
        assertTrue(run.out().matches("Hello from agent [012]\n"), run.out());
        assertEquals("", run.err());
    }
}
