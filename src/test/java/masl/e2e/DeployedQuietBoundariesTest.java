package masl.e2e;

import java.time.Duration;
import java.util.List;
import masl.testing.MaslMission;
import masl.testing.MissionPlatform;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A translated program whose deployed agent passes its boundaries with nothing to do in its
 * container: a loop that polls a local until a reaction sets it, in an asynchronous block, whose step
 * boundaries and loop heads cost no message, ends when the event comes, as in-process (its emitter
 * sleeps a little first, so that it comes most often while the loop runs).
 */
@Timeout(120)
class DeployedQuietBoundariesTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);

    @Test
    void aPollingLoopEndsWhenItsEventComes() {
        MaslMission mission = MaslMission.fromString("polls.masl", """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                asynchronous entry main (true) {
                  shared event go;
                  shared int ready = 0;
                  local boolean heard = false;
                  local int polls = 0;
                  if (.getProxyID() == 0) {
                    ready = 1;
                    while (!heard) { polls = polls + 1; }
                    .logln("a heard go");
                  } else {
                    while (ready < 1) { }
                    .sleep(100);
                    emit(go);
                  }
                  react (go) { heard = true; resume; }
                }
                """).timeout(TIMEOUT);
        mission.run().assertJournal("a heard go\n");
        for (MissionPlatform deployment : List.<MissionPlatform>of(DeployedInMemory.everyAgent(),
                DeployedInMemory.spread(), DeployedInMemory.agents("a"))) {
            mission.runOn(deployment).assertJournal("a heard go\n");
        }
    }
}
