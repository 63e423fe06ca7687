package masl.e2e;

import java.nio.file.Path;
import masl.testing.MaslMission;
import org.junit.jupiter.api.Test;

/** How a user tests a mission: one run as masl run would, then 200 explored schedules. */
class UserStyleMissionTest {

    private final MaslMission e2 = MaslMission.fromFile(Path.of("src/test/resources/examples/e2_shared_and_local.masl"));

    @Test
    void theReportComesBeforeEveryAgentsOwnLine() {
        e2.run().assertJournal("n=5\nmine=1\nmine=1\nmine=1\nmine=1\nmine=1\n");
        e2.explore(200).assertEveryRun(run -> run.assertEveryBefore("n=5", "mine=1"));
    }
}
