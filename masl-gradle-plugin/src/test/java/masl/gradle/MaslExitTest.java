package masl.gradle;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** What a failed maslRun says of masl's exit status: what the status means, as masl's README and the Maven plug-in say it. */
class MaslExitTest {

    private static String failedWith(int status) {
        return MaslExit.describe("team", new RuntimeException("Process 'command 'java'' finished with non-zero exit value "
                + status), "");
    }

    @Test
    void aLostTraceIsAmongTheMeaningsOfStatusTwo() {
        assertEquals("mission team failed (masl exit status 2: the mission failed, deadlocked, timed out or was stopped,"
                + " or its journal or trace could not be written); masl's report is above", failedWith(2));
    }

    @Test
    void everyStatusMaslGivesHasItsMeaning() {
        assertEquals("mission team failed (masl exit status 71: out of memory before the mission ran: the program is too"
                + " large for masl's heap); masl's report is above", failedWith(71));
        assertEquals("mission team failed (masl exit status 74: an output could not be written); masl's report is above",
                failedWith(74));
        assertEquals("mission team failed (masl exit status 143: stopped by SIGTERM); masl's report is above", failedWith(143));
    }
}
