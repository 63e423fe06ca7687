package masl.sim.clock;

import java.util.List;
import masl.runtime.scheduling.AgentTask;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.scheduling.Scheduler;
import masl.sim.physics.PhysicsWorld;

/**
 * Runs a simulated mission with the physics on its own thread at a fixed step (paced by the
 * settings' real-time factor) and the agents on a {@link PoolScheduler}: the realistic mode,
 * where agents and robots run concurrently and runs may differ. Sleeps and timeouts
 * ({@link #scheduleAfter}) follow simulated time: they are due a whole number of steps later and
 * are handed, right after that step, to the pool's timer thread (not run on the physics thread,
 * which holds the world's lock then: a wake-up must never wait for an agent that waits for the world).
 *
 * <p>{@link #start} starts the world's thread; {@link #shutdown} stops it and the pool.
 */
public final class ThreadedSimulationScheduler implements Scheduler {

    private final PhysicsWorld world;
    private final Scheduler agents;
    private final StepTimers timers;

    /** @param world not yet started; this scheduler starts and stops its thread */
    public ThreadedSimulationScheduler(PhysicsWorld world) {
        this.world = world;
        this.agents = new PoolScheduler();
        this.timers = new StepTimers(world.settings().stepSize());
        world.addStepListener(stepped -> timers.takeDue(stepped.stepCount()).forEach(due -> agents.scheduleAfter(0, due)));
    }

    @Override
    public void start(List<? extends AgentTask> tasks) {
        agents.start(tasks);
        world.start();
    }

    @Override
    public void schedule(AgentTask agent) {
        agents.schedule(agent);
    }

    @Override
    public void scheduleAfter(long delayMillis, Runnable action) {
        timers.add(world.stepCount(), delayMillis, action);
    }

    @Override
    public int stepsPerSlice() {
        return agents.stepsPerSlice();
    }

    @Override
    public void shutdown() {
        try {
            world.stop();
        } finally {
            agents.shutdown();
        }
    }
}
