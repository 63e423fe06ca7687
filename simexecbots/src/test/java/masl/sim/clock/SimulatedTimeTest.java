package masl.sim.clock;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import masl.agents.Default;
import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.scheduling.Scheduler;
import masl.sim.physics.PhysicsSettings;
import masl.sim.physics.PhysicsWorld;
import org.junit.jupiter.api.Test;

/** {@code sleep} follows simulated time in both simulation schedulers. */
class SimulatedTimeTest {

    /** Sleeps {@code ms} of mission time, then notes the world's simulated time. */
    private static final class SleepThenNote extends AgentProgram {
        private final long ms;
        private final PhysicsWorld world;
        private final List<Double> noted;

        SleepThenNote(long ms, PhysicsWorld world, List<Double> noted) {
            this.ms = ms;
            this.world = world;
            this.noted = noted;
        }

        @Override
        protected void resume(AgentContext ctx) {
            if (pc == 0) {
                pc = 1;
                if (!ctx.sleep(ms)) {
                    return;
                }
            }
            noted.add(world.simulatedTime());
            ctx.finish();
        }
    }

    private static List<Double> run(PhysicsWorld world, Scheduler scheduler, long... sleeps) throws InterruptedException {
        List<Double> noted = new CopyOnWriteArrayList<>();
        Mission.Builder builder = Mission.builder().scheduler(scheduler);
        for (long ms : sleeps) {
            builder.agent("a" + ms, new Default(), impl -> new SleepThenNote(ms, world, noted));
        }
        MissionOutcome outcome = builder.build().run(Duration.ofSeconds(30));
        assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
        return noted;
    }

    @Test
    void lockStepSleepsTakeExactlyTheirSimulatedTime() throws InterruptedException {
        try (PhysicsWorld world = new PhysicsWorld(PhysicsSettings.defaults().withRealTimeFactor(0))) {
            List<Double> noted = run(world, new LockStepScheduler(world, 1, 64), 2500, 400);
            assertEquals(List.of(0.4, 2.5), noted.stream().map(t -> Math.round(t * 100) / 100.0).toList(),
                    "each agent wakes at its own simulated time, the shorter sleep first");
        }
    }

    @Test
    void aSleepOfPartOfAStepLastsOneWholeStep() throws InterruptedException {
        try (PhysicsWorld world = new PhysicsWorld(PhysicsSettings.defaults().withRealTimeFactor(0))) {
            List<Double> noted = run(world, new LockStepScheduler(world, 1, 64), 3);
            assertEquals(0.01, noted.get(0), 1e-9);
        }
    }

    @Test
    void threadedSleepsFollowTheWorldsThread() throws InterruptedException {
        // As fast as possible: the 30 simulated seconds pass in far less wall-clock time.
        try (PhysicsWorld world = new PhysicsWorld(PhysicsSettings.defaults().withRealTimeFactor(0))) {
            List<Double> noted = run(world, new ThreadedSimulationScheduler(world), 30_000);
            assertTrue(noted.get(0) >= 30.0 - 1e-9, "woke at simulated " + noted.get(0));
            assertTrue(!world.isRunning(), "the mission's end stopped the physics thread");
        }
    }
}
