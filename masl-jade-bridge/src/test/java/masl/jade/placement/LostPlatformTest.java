package masl.jade.placement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.trust.ForgedMessagesTest;
import masl.jade.trust.MissionSecret;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A container that no coordinator placed bodies on ends its mission when its platform shuts down,
 * saying why, instead of waiting for ever for a placement that cannot come; leaving then, while the
 * shutdown ends it, it joins the next platform, as a serving container does mission after mission.
 */
@Timeout(120)
class LostPlatformTest {

    @Test
    void aContainerNeverPlacedEndsWhenItsPlatformShutsDown() throws Exception {
        JadePlatform main = JadePlatform.start(JadeOptions.mainContainer());
        try (MaslContainer container = ForgedMessagesTest.container(main, "c2", MissionSecret.generate())) {
            main.close();
            assertTrue(container.awaitMissionEnd(Duration.ofSeconds(60)), "still waiting a minute after its platform");
            assertEquals(Optional.of("the platform is gone (its main container shut down)"), container.lostPlatform());
            assertEquals(List.of(), container.hostedAgents());
        } finally {
            main.close();
        }
    }

    @Test
    void aContainerLeavingWhileItsPlatformShutsDownJoinsTheNextPlatform() throws Exception {
        for (int mission = 1; mission <= 3; mission++) {
            JadePlatform main = JadePlatform.start(JadeOptions.mainContainer());
            Thread shutdown = new Thread(main::close, "platform-shutdown");
            try {
                MaslContainer container = ForgedMessagesTest.container(main, "c2", MissionSecret.generate());
                shutdown.start();
                assertTrue(container.awaitMissionEnd(Duration.ofSeconds(60)), "mission " + mission + ": still waiting");
                assertEquals(Optional.of("the platform is gone (its main container shut down)"), container.lostPlatform());
                container.leave();
            } finally {
                shutdown.join();
                main.close();
            }
        }
    }
}
