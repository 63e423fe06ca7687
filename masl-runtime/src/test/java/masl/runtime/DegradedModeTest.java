package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Degraded modes (MASL §11): agents drain their battery (an attribute a primitive updates), switch
 * to state {@code degraded} when it falls under 50, and are re-elected into the block whose test
 * reads their state. Agent {@code me} drains 20, 30 or 60 per round. It reads its proxy id while
 * in {@code default}: {@code degraded} denies it {@code getProxyID}.
 */
@Timeout(120)
class DegradedModeTest {

    private static final MaslProgram DRAINING = MaslProgram.of("degraded.masl", MaslProgram.header(3) + """
            asynchronous entry main (true) {
              local int me = .getProxyID();
              .battery = 100;
              asynchronous entry work (getAcceptState() == "default") {
                .drain(me == 0 ? 20 : me == 1 ? 30 : 60);
                .logln(me + " works at " + .battery);
                if (.battery < 50) setAcceptState("degraded");
                reelect;
              }
              asynchronous entry rest (getAcceptState() == "degraded") {
                .logln(me + " degraded at " + .battery);
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void agentsSwitchToTheDegradedStateAndAreReelectedIntoItsBlock(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            String journal = DRAINING.run(driver).journal();
            assertEquals(List.of("0 works at 80", "0 works at 60", "0 works at 40", "0 degraded at 40"),
                    linesOf(journal, "0 "), journal);
            assertEquals(List.of("1 works at 70", "1 works at 40", "1 degraded at 40"), linesOf(journal, "1 "),
                    journal);
            assertEquals(List.of("2 works at 40", "2 degraded at 40"), linesOf(journal, "2 "), journal);
            assertEquals(9, journal.lines().count(), journal);
        }
    }

    private static List<String> linesOf(String journal, String prefix) {
        return journal.lines().filter(line -> line.startsWith(prefix)).toList();
    }
}
