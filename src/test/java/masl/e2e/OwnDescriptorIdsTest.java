package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.function.Consumer;
import java.util.stream.LongStream;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.Schedule;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Member ids belong to their descriptor (agent-types.md, components.md "Agent path"):
 * a redefinition with an id of its own, and a user's own Default.xml next to the program, which is
 * the root type with its own ids and states.
 */
@Timeout(60)
class OwnDescriptorIdsTest {

    private static final int SEEDS = 50;
    private static final int RUNS = 10;

    /**
     * Scribe redefines Worker's logln as S1. Worker's {@code degraded} names logln D4 (self and group
     * may invoke it): it still applies. Scribe's {@code hushed} names it S1 (only the agent itself).
     */
    @Test
    void aStateOfTheSupertypeAndOneOfTheSubtypeApplyToARedefinitionWithItsOwnId() {
        MaslMission mission = MaslMission.fromString("scribes.masl", """
                import workers/Scribe.xml;
                Scribe s, t = newAgent(Scribe);
                synchronous entry main (true) {
                  local Scribe other = s;
                  if (.getProxyID() == 0) other = t; else other = s;
                  setAcceptState("degraded");
                  other.logln(.getProxyID() + " writes in degraded");
                  setAcceptState("hushed");
                  other.logln(.getProxyID() + " writes in hushed");
                  .logln(.getProxyID() + " writes its own line in hushed");
                  react (timeout) { .logln(.getProxyID() + " denied " + getMessageFromEvent(timeout)); resume; }
                }
                """);
        everyRun(mission, run -> run.assertLinesInAnyOrder("0 writes in degraded", "1 writes in degraded",
                "0 denied logln", "1 denied logln", "0 writes its own line in hushed", "1 writes its own line in hushed"));
    }

    @Test
    void aProgramNextToItsOwnDefaultXmlLoadsAndRunsWithItsIdsAndStates() {
        MaslMission crew = MaslMission.fromFile(Path.of("src/test/resources/own-default/crew.masl"));
        everyRun(crew, run -> run.assertLinesInAnyOrder("0 sees 2 agents, the other a Default: true",
                "1 sees 2 agents, the other a Default: true", "0 hears hello agent 0 from 1", "1 hears hello agent 1 from 0",
                "0 denied tally", "1 denied tally", "0 counted 1, was told 0 in guarded",
                "1 counted 1, was told 0 in guarded"));
    }

    @Test
    void maslRunRunsTheProgramNextToItsOwnDefaultXml() {
        MaslCommand run = MaslCommand.run("run", "src/test/resources/own-default/crew.masl");
        assertEquals(0, run.status(), run::toString);
        assertEquals(8, run.out().lines().count(), run::toString);
    }

    private static void everyRun(MaslMission mission, Consumer<MissionRun> property) {
        for (int run = 0; run < RUNS; run++) {
            property.accept(mission.run());
            property.accept(mission.runWith(Schedule.threads()));
        }
        mission.explore(LongStream.range(0, SEEDS), 0).assertEveryRun(property);
    }
}
