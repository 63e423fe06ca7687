package masl.runtime.scheduling;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;

/**
 * Runs each agent on a platform thread of its own that parks while the agent waits: the thesis's
 * model, the one inside JADE's threaded behaviours, and {@code --threads} in-process. The program
 * objects and the runtime are the same as with {@link PoolScheduler}; only who runs the slices
 * differs. It does not scale to many agents (about 46 lock-step steps/s for 1,000 agents).
 */
public final class ThreadPerAgentScheduler implements Scheduler {

    private final List<Thread> threads = new ArrayList<>();
    private final ScheduledThreadPoolExecutor timer;
    /** One permit per pending slice, indexed by agent id; one each at start. */
    private Semaphore[] runnable;

    public ThreadPerAgentScheduler() {
        timer = new ScheduledThreadPoolExecutor(1, PoolScheduler.daemon("masl-timer"));
        timer.setRemoveOnCancelPolicy(true);
    }

    @Override
    public synchronized void start(List<? extends AgentTask> agents) {
        // Some of a mission's agents only, maybe (the others run elsewhere): indexed by proxy id.
        runnable = new Semaphore[agents.stream().mapToInt(AgentTask::id).max().orElse(-1) + 1];
        for (AgentTask agent : agents) {
            Semaphore permits = new Semaphore(1);
            runnable[agent.id()] = permits;
            Thread thread = new Thread(() -> drive(agent, permits), "masl-agent-" + agent.id());
            thread.setDaemon(true);
            threads.add(thread);
        }
        threads.forEach(Thread::start);
    }

    /** Runs the agent's slices until the mission ends: a finished agent still serves invocations. */
    private static void drive(AgentTask agent, Semaphore permits) {
        try {
            while (true) {
                permits.acquire();
                agent.runSlice();
            }
        } catch (InterruptedException missionEnded) {
            // shutdown() interrupts the thread: it ends with the mission.
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
        return Integer.MAX_VALUE;
    }

    @Override
    public synchronized void shutdown() {
        timer.shutdownNow();
        threads.forEach(Thread::interrupt);
    }
}
