package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** JADE's notices on a JADE run's standard error: all but the one an agent's deletion prints by chance. */
class JadeNoticesTest {

    private final ByteArrayOutputStream err = new ByteArrayOutputStream();
    private final PrintStream notices = new JadeNotices(new PrintStream(err, true, StandardCharsets.UTF_8));

    private String written() {
        return err.toString(StandardCharsets.UTF_8);
    }

    @Test
    void theNoticeOfAnAgentInterruptedInItsDeletionIsDropped() {
        notices.println("Agent a@127.0.0.1:1099/JADE interrupted while waiting");
        assertEquals("", written());
    }

    @Test
    void everyOtherNoticeReachesStandardErrorAsWritten() {
        notices.println("Agent a@127.0.0.1:1099/JADE interrupted while waiting for its mother");
        notices.println("*******************MTP addresses*******");
        notices.print("no line break");
        notices.println((String) null);
        assertEquals("Agent a@127.0.0.1:1099/JADE interrupted while waiting for its mother\n"
                + "*******************MTP addresses*******\nno line breaknull\n", written().replace(System.lineSeparator(), "\n"));
    }

    /** The words dropped are JADE's own, as its agent class holds them: a JADE that words it otherwise fails here. */
    @Test
    void theDroppedWordsAreJades() throws IOException {
        try (InputStream agentClass = JadeNoticesTest.class.getClassLoader().getResourceAsStream("jade/core/Agent.class")) {
            assertNotNull(agentClass, "JADE is on the class path");
            String constants = new String(agentClass.readAllBytes(), StandardCharsets.ISO_8859_1);
            assertTrue(constants.contains(" interrupted while waiting"), "JADE no longer prints this notice");
        }
    }
}
