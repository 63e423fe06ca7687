package sample;

import java.nio.file.Path;
import masl.testing.MaslMission;
import org.junit.jupiter.api.Test;

class CountTest {

    private final MaslMission count = MaslMission.fromFile(Path.of("src/main/masl/count.masl"));
    private final MaslMission click = MaslMission.fromFile(Path.of("src/test/masl/click.masl"));

    @Test
    void everyClickIsCounted() {
        count.run().assertJournal("total=9\n");
    }

    @Test
    void noClickIsLostUnderAnySchedule() {
        count.explore(200).assertEveryRun(run -> run.assertJournal("total=9\n"));
    }

    @Test
    void aMissionOfTheTestsUsesTheAgentTypesOfTheMainCode() {
        click.run().assertJournal("clicks=3\n");
    }
}
