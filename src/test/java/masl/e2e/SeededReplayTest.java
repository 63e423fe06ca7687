package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.Schedule;
import org.junit.jupiter.api.Test;

/**
 * A seeded run replays byte for byte, also when asynchronous primitives run under a call timeout
 * (their bodies then run on a thread of their own, which the seeded scheduler must wait for as it
 * waits for a body without a timeout).
 */
class SeededReplayTest {

    @Test
    void launchedPrimitivesUnderACallTimeoutReplayUnderEverySeed() {
        MaslMission mission = MaslMission.fromString("planners.masl", """
                import RoutePlanner.xml as RoutePlanner;
                RoutePlanner p0, p1 = newAgent(RoutePlanner);
                asynchronous entry main (true) {
                    LLabel plan;
                    local String route;
                    plan.route = .route(0, 0, 1 + .getProxyID(), 1);
                    .logln(.getProxyID() + " launched");
                    while (!plan.isFinished()) {}
                    .logln(.getProxyID() + " " + route);
                }
                """).callTimeout(Duration.ofSeconds(1));
        List<Long> differing = new ArrayList<>();
        for (long seed = 0; seed < 100; seed++) {
            MissionRun first = mission.runWith(Schedule.seed(seed)).assertCompleted();
            MissionRun again = mission.runWith(Schedule.seed(seed)).assertCompleted();
            if (!first.journal().equals(again.journal()) || !first.trace().equals(again.trace())) {
                differing.add(seed);
            }
        }
        assertEquals(List.of(), differing, "seeds whose two runs differ");
    }
}
