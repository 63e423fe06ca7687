package masl.jade;

import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.ThreadedBehaviourFactory;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import masl.runtime.scheduling.AgentTask;
import masl.runtime.scheduling.Scheduler;

/**
 * Runs each MASL agent inside its JADE agent, in a threaded behaviour (a thread of its own that JADE
 * created for the behaviour): the runtime's thread-per-agent model (components.md, "Execution
 * model"), with JADE's threads. The thread parks while the agent waits and runs a slice each time
 * the agent is made runnable, until the mission ends.
 */
final class ThreadedBehaviourScheduler implements Scheduler {

    private static final long JOIN_MILLIS = 10_000;
    /**
     * The step boundaries and loop iterations an agent passes before its slice ends and its driver
     * runs the next one. The thread is the agent's own, so this is not for fairness: a driver learns
     * that the mission has ended only between slices, and an agent spinning in a loop (polling a
     * primitive in an empty {@code while}) would otherwise never end its slice, nor its thread.
     * Ending a slice costs a permit handed to itself; a few hundred steps make that negligible.
     */
    private static final int STEPS_PER_SLICE = 256;

    private List<? extends Agent> hosts = List.of();
    private final ThreadedBehaviourFactory threads = new ThreadedBehaviourFactory();
    private final ScheduledThreadPoolExecutor timer;
    /** One permit per pending slice, indexed by agent id. */
    private Semaphore[] runnable;
    private Driver[] drivers;

    ThreadedBehaviourScheduler() {
        timer = new ScheduledThreadPoolExecutor(1, runnable -> {
            Thread thread = new Thread(runnable, "masl-timer");
            thread.setDaemon(true);
            return thread;
        });
        timer.setRemoveOnCancelPolicy(true);
    }

    /**
     * The JADE agent hosting each MASL agent's program, indexed by proxy id, all started: before
     * {@link #start}. The coordinator hosts the programs of the agents placed in other containers.
     */
    synchronized void attach(List<? extends Agent> agents) {
        hosts = List.copyOf(agents);
    }

    /** Runs these agents, each in its JADE agent; they may be some of the mission's only (the others run elsewhere). */
    @Override
    public synchronized void start(List<? extends AgentTask> agents) {
        for (AgentTask agent : agents) {
            if (agent.id() >= hosts.size()) {
                throw new IllegalArgumentException("agent " + agent.id() + " has no JADE agent: " + hosts.size());
            }
        }
        runnable = new Semaphore[hosts.size()];
        drivers = new Driver[hosts.size()];
        // Every agent is runnable (one permit) before any driver thread exists.
        for (AgentTask agent : agents) {
            runnable[agent.id()] = new Semaphore(1);
        }
        for (AgentTask agent : agents) {
            drivers[agent.id()] = new Driver(agent, runnable[agent.id()]);
            hosts.get(agent.id()).addBehaviour(threads.wrap(drivers[agent.id()]));
        }
    }

    @Override
    public void schedule(AgentTask agent) {
        runnable[agent.id()].release();
    }

    @Override
    public void scheduleAfter(long delayMillis, Runnable action) {
        timer.schedule(action, delayMillis, TimeUnit.MILLISECONDS);
    }

    @Override
    public int stepsPerSlice() {
        return STEPS_PER_SLICE;
    }

    /**
     * Stops the drivers (a slice under way is interrupted: a primitive blocked in it ends with
     * {@code InterruptedException}) and the timer, and waits, bounded, until their threads have ended.
     */
    @Override
    public synchronized void shutdown() {
        timer.shutdownNow();
        List<Driver> started = drivers == null ? List.of() : Arrays.stream(drivers).filter(Objects::nonNull).toList();
        started.forEach(Driver::stop);
        try {
            long deadline = System.currentTimeMillis() + JOIN_MILLIS;
            for (Driver driver : started) {
                driver.join(Math.max(1, deadline - System.currentTimeMillis()));
            }
            timer.awaitTermination(Math.max(1, deadline - System.currentTimeMillis()), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * The behaviour run in its own thread: one slice per permit, until stopped. {@link #stop()} and
     * the start of the thread may race: the thread publishes itself before it reads the flag, and
     * {@code stop} sets the flag before it reads the thread, so one of them sees the other.
     */
    private static final class Driver extends Behaviour {
        private static final long serialVersionUID = 1L;

        private final transient AgentTask agent;
        private final transient Semaphore permits;
        private transient volatile Thread thread;
        private volatile boolean stopped;
        private volatile boolean done;

        Driver(AgentTask agent, Semaphore permits) {
            this.agent = agent;
            this.permits = permits;
        }

        @Override
        public void action() {
            thread = Thread.currentThread();
            try {
                while (!stopped) {
                    permits.acquire();
                    if (!stopped) {
                        agent.runSlice();
                    }
                }
            } catch (InterruptedException missionEnded) {
                // stop() interrupts the thread: it ends with the mission.
            } finally {
                done = true;
            }
        }

        @Override
        public boolean done() {
            return done;
        }

        void stop() {
            stopped = true;
            permits.release();
            Thread running = thread;
            if (running != null) {
                running.interrupt();
            }
        }

        /** Waits until the driver's thread has ended, if it ever started. */
        void join(long millis) throws InterruptedException {
            Thread running = thread;
            if (running != null) {
                running.join(millis);
            }
        }
    }
}
