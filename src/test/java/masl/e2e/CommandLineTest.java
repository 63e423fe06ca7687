package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import masl.translator.cli.Masl;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** {@code masl run} on the project's own missions, as the README shows it. */
@Timeout(120)
class CommandLineTest {

    @Test
    void helloPrintsOneGreetingFromOneOfItsThreeAgents() {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = new Masl(new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8)).run("run", "missions/hello.masl");
        String journal = out.toString(StandardCharsets.UTF_8);
        assertEquals(0, status, err.toString(StandardCharsets.UTF_8));
        assertTrue(journal.matches("Hello from agent [012]\n"), journal);
        assertEquals("", err.toString(StandardCharsets.UTF_8));
    }
}
