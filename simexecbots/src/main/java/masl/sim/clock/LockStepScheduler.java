package masl.sim.clock;

import java.util.List;
import java.util.concurrent.Executor;
import masl.runtime.scheduling.AgentTask;
import masl.runtime.scheduling.PrimitiveTurn;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.SeededDraw;
import masl.sim.physics.PhysicsWorld;

/**
 * Runs a simulated mission on one thread that also steps the physics: the same scenario, seed and
 * program give the same run, bit for bit (trajectories, journal, trace). Like
 * {@link masl.runtime.scheduling.SeededScheduler}, the next agent is drawn from the runnable ones by a seeded
 * generator after every step boundary; unlike it, time is the physics world's.
 *
 * <p><b>Simulated time.</b> The world takes one step when no agent is runnable (everyone sleeps or
 * waits) and also after every {@code slicesPerStep} slices, so that a program polling a sensor in a
 * loop sees the world move: instructions take simulated time too. Sleeps and timeouts
 * ({@link #scheduleAfter}) are due a whole number of steps later and run right after that step.
 *
 * <p>The bodies of launched asynchronous primitives are drawn with the agents' slices
 * ({@link PrimitiveTurn}), so when a launch completes is reproducible too. Agents' primitives must
 * not block on the world (the world only moves on this thread); the robot primitives of
 * {@code masl.agents} never do. A wake-up from another thread is waited for.
 */
public final class LockStepScheduler implements Scheduler {

    private final PhysicsWorld world;
    private final int slicesPerStep;
    private final StepTimers timers;
    /** Runnable agents' slices and primitives' turns. */
    private final SeededDraw runnable;
    private int slicesSinceStep;
    private Thread worker;
    private volatile boolean shutDown;

    /**
     * @param world         stepped by this scheduler only, never {@link PhysicsWorld#start() started}
     * @param seed          seeds the order in which runnable agents are drawn
     * @param slicesPerStep slices run before the world takes a step although agents are runnable, &gt; 0
     */
    public LockStepScheduler(PhysicsWorld world, long seed, int slicesPerStep) {
        if (slicesPerStep <= 0) {
            throw new IllegalArgumentException("slicesPerStep: " + slicesPerStep);
        }
        this.world = world;
        this.slicesPerStep = slicesPerStep;
        this.runnable = new SeededDraw(seed);
        this.timers = new StepTimers(world.settings().stepSize());
    }

    @Override
    public synchronized void start(List<? extends AgentTask> agents) {
        agents.forEach(agent -> runnable.add(agent::runSlice));
        worker = new Thread(this::work, "masl-lockstep");
        worker.setDaemon(true);
        worker.start();
    }

    private void work() {
        try {
            while (!shutDown) {
                Runnable next = next();
                if (next != null) {
                    next.run();
                }
            }
        } catch (InterruptedException missionEnded) {
            // shutdown() interrupts the worker: it ends with the mission.
        }
    }

    /** The next task to run, or null after a world step (whose due timers have run). */
    private Runnable next() throws InterruptedException {
        synchronized (this) {
            while (runnable.isEmpty() && timers.isEmpty()) {
                wait();
            }
            if (!runnable.isEmpty() && slicesSinceStep < slicesPerStep) {
                slicesSinceStep++;
                return runnable.draw();
            }
            slicesSinceStep = 0;
        }
        world.step();
        timers.takeDue(world.stepCount()).forEach(Runnable::run);
        return null;
    }

    @Override
    public synchronized void schedule(AgentTask agent) {
        runnable.add(agent::runSlice);
        notifyAll();
    }

    /**
     * The body of an asynchronous primitive is drawn among the agents, at the simulated time it was
     * launched, and takes one slice but no simulated time of its own ({@link PrimitiveTurn}).
     */
    @Override
    public synchronized void runPrimitive(Runnable body, Executor threads) {
        runnable.add(new PrimitiveTurn(body, threads)::run);
        notifyAll();
    }

    @Override
    public synchronized void scheduleAfter(long delayMillis, Runnable action) {
        timers.add(world.stepCount(), delayMillis, action);
        notifyAll();
    }

    @Override
    public int stepsPerSlice() {
        return 1;
    }

    /**
     * Stops running slices and stepping the world after the current slice or step, without waiting:
     * callable from the worker itself (a step listener ending the run at a simulated time).
     */
    public void halt() {
        shutDown = true;
    }

    /**
     * Stops the worker and waits until it has ended, so that the world is no longer stepped when
     * this returns and its owner may close it. Called by the mission from another thread.
     */
    @Override
    public void shutdown() {
        Thread running;
        synchronized (this) {
            shutDown = true;
            running = worker;
        }
        if (running == null || running == Thread.currentThread()) {
            return;
        }
        running.interrupt();
        boolean interrupted = false;
        while (running.isAlive()) {
            try {
                running.join();
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }
}
