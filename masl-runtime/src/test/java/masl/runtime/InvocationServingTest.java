package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.Watching;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The runtime side of invocations (MASL §5, §9): a blocked or finished callee still serves the
 * invocations queued for it, and a caller waits for a result without holding a thread.
 */
@Timeout(120)
class InvocationServingTest {

    /**
     * Agent 1 (the callee) waits at the entry barrier of a locked block; agent 0 invokes it, logs
     * the result, and then releases the block.
     */
    private static final MaslProgram HELD_CALLEE = MaslProgram.of("held.masl", 2, """
            Entry gate;
            asynchronous entry main (true) {
              scalar entry setup (true) { gate.lock(); }
              while (gate.getLockPolicy() == "free") {}
              asynchronous entry call (.getProxyID() == 0) {
                while (gate.getWaitingInCount() == 0) {}
                .logln("served " + a1.getProxyID());
                gate.release();
              }
              synchronous entry gate (.getProxyID() == 1) { .logln("in gate"); }
            }
            """);

    /**
     * Agent 1 (the callee) skips main and finishes; agent 0 spins until then ({@code signal(1)}
     * answers 1 once agent 1's program has finished: a primitive in the condition makes the loop a
     * spinning one, which the runtime does not park), invokes it and logs the result.
     */
    private static final MaslProgram FINISHED_CALLEE = MaslProgram.of("finished.masl", 2, """
            asynchronous entry main (.getProxyID() == 0) {
              while (.signal(1) == 0) {}
              .logln("served " + a1.getProxyID());
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aCalleeBlockedAtAnEntryBarrierStillServesItsCallers(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("served 1\nin gate\n", HELD_CALLEE.run(driver).journal());
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aCalleeThatHasLeftMainStillServesItsCallers(Driver driver) throws InterruptedException {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            List<TestAgent> agents = new ArrayList<>();
            AtomicReference<Mission> mission = new AtomicReference<>();
            BooleanSupplier calleeFinished = () -> mission.get().agentOf(agents.get(1)).isDone();
            mission.set(FINISHED_CALLEE.newMission(MaslProgram.recording(() -> new Watching(calleeFinished), agents))
                    .scheduler(driver.newScheduler()).build());
            MissionOutcome outcome = mission.get().run(Duration.ofSeconds(20)).requireCompleted();
            assertEquals("served 1\n", outcome.journal());
        }
    }
}
