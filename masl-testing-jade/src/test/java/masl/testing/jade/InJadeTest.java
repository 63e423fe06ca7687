package masl.testing.jade;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.jade.greeting.GreeterAgent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * A mission under test inside the JADE platform of {@link JadePlatformExtension}, calling a plain
 * JADE agent the test started there; the same mission in-process calls its stand-in class instead.
 */
@Timeout(120)
class InJadeTest {

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    private static final MaslMission GREET = MaslMission.fromFile(Path.of("src/test/masl/greet.masl"));

    @Test
    void aMissionInJadeCallsAPlainJadeAgent() throws Exception {
        JADE.platform().container().acceptNewAgent("greeter", new GreeterAgent()).start();

        MissionRun run = GREET.runOn(JADE.missionPlatform()).assertJournal("hello team, from JADE\n");

        AssertionError failure = assertThrows(AssertionError.class, () -> run.assertJournal("hello\n"));
        assertTrue(failure.getMessage().startsWith("src/test/masl/greet.masl in JADE (container "),
                failure.getMessage());
        assertTrue(!failure.getMessage().contains("--seed"), "a JADE run has no seed to replay: " + failure.getMessage());
    }

    @Test
    void inProcessTheStandInAnswers() {
        GREET.run().assertJournal("hello team\n");
    }
}
