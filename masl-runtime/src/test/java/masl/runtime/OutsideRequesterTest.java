package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicReference;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A request from outside the mission (a FIPA agent through the JADE bridge) is an "other" for
 * permeability (MASL §11): agent 0 takes a state, submits such a request for its own {@code nop}
 * through {@link Mission#submitInvocation(int, String, Runnable, Runnable)}, and serves it at its
 * next step boundary: it runs in {@code x1} (o may invoke) and {@code default}, is denied in
 * {@code x6} (only u and g) and {@code nothing}.
 */
@Timeout(120)
class OutsideRequesterTest {

    /**
     * {@code signal(0)} submits the request, of zero duration; the step boundary of the first
     * {@code setAcceptState} serves it in that state; the agent logs in {@code default}.
     */
    private static final String REQUESTING = """
            scalar entry main (true) {
              .signal(0);
              setAcceptState("%1$s");
              setAcceptState("default");
              .log("%1$s: ");
            }
            """;

    /** An agent whose {@code signal} submits a request for its own {@code nop} from outside the mission. */
    private static final class Requesting extends TestAgent {
        private final AtomicReference<Mission> mission;

        Requesting(AtomicReference<Mission> mission) {
            this.mission = mission;
        }

        @Override
        public int signal(int value) {
            mission.get().submitInvocation(0, "nop", () -> log("ran "), () -> log("denied "));
            return value;
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aRequestFromOutsideIsFilteredAsOther(Driver driver) throws InterruptedException {
        StringBuilder journals = new StringBuilder();
        for (String state : new String[] {"x1", "default", "x6", "nothing"}) {
            AtomicReference<Mission> mission = new AtomicReference<>();
            mission.set(MaslProgram.of("outside-" + state + ".masl", 1, REQUESTING.formatted(state))
                    .newMission(() -> new Requesting(mission)).scheduler(driver.newScheduler()).build());
            journals.append(mission.get().run(Duration.ofSeconds(20)).requireCompleted().journal()).append('|');
        }
        assertEquals("ran x1: |ran default: |denied x6: |denied nothing: |", journals.toString());
    }
}
