package masl.runtime;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import masl.runtime.scheduling.WakeUps;

/**
 * The deadlock watchdog of a {@link Mission}. A mission is <em>deadlocked</em> when some program has not finished
 * and no agent will ever run again (its program or a slice serving invocations on its behalf)
 * unless something outside the mission acts: an outside invocation, {@link Mission#stop()}. The watchdog
 * reports exactly that ({@code DEADLOCKED}, or {@code FAILED} if an agent died); it never reports a
 * mission that can still make progress, however long a thread is preempted. It rests on three rules.
 * <ol>
 * <li>An agent is <em>idle</em> ({@code Agent.isIdle}) when it runs nothing until woken: parked or
 * done with no invocation queued, or parked in {@code wait(state)}. A <em>wake-up</em> ends that:
 * an unpark ({@code PARKED → SCHEDULED}), the serving slice of an agent in {@code wait(state)}, an
 * invocation queued, the timeout of a wait that leaves invocations queued.</li>
 * <li>Every wake-up and every queued invocation is <em>counted</em> ({@link WakeUps}) before it
 * happens.</li>
 * <li>From its count to its act, the thread making it either runs a slice of an agent that is not
 * idle (the program or serving slice that trips a barrier, releases, emits, writes a shared
 * variable, invokes), or holds a <em>pending</em> wake-up, begun (and counted) before: a sleep or a
 * timed wait from the call to the timer's unpark, an awaited future from the await to the unpark,
 * an asynchronous primitive while it runs, an outside invocation ({@link Mission#submitInvocation}) for
 * the whole call, and the end of a slice of an agent in {@code wait(state)} from before it turns
 * {@code PARKED} to its serving slice being scheduled.</li>
 * </ol>
 * Every {@link Mission#WATCHDOG_PERIOD} the watchdog <em>looks</em>: it reads the counts (one atomic word),
 * every agent, and the counts again. A look is quiet if nothing is pending, every agent is idle,
 * every agent that is done has been counted out of the running ones (an agent turns {@code DONE}
 * before the mission counts it out, and builds its report in between: until then it is ending, not
 * idle) and the counts did not move; two quiet looks in a row with the same counts end the mission.
 *
 * <p>Why that is a deadlock: the counts did not move from the first read of the first look to the
 * last read of the second, and nothing was pending at the first read, so nothing was pending
 * throughout (a pending wake-up counts when it begins). Any wake-up or queued invocation in that
 * span was therefore counted before it, by a slice of a non-idle agent X that ran on until the act
 * (rule 3); had the act come after the first look read X, that look would have seen X not idle. So
 * nothing wakes anyone after the first look, every agent the second look saw idle is still idle at
 * its end, and no pending wake-up, nor any slice that could make one, is left: the end of a slice
 * whose agent has just parked wakes nobody but through rule 3. One look would not do: a slice can
 * wake an agent the look has already read as idle, then park before the look reads it. In a mission
 * {@linkplain Mission.Builder#openToOutsideInvocations() open to outside invocations}, an agent parked in a
 * busy-wait is not idle, since an outside invocation is a change it waits for.
 */
final class DeadlockWatchdog {

    private final List<Agent> agents;
    private final WakeUps wakeUps;
    /** The mission's agents whose programs it has not counted out yet. */
    private final AtomicInteger running;
    private final boolean openToOutsideInvocations;
    private boolean lastLookIdle;
    private long lastIdleLook;

    DeadlockWatchdog(List<Agent> agents, WakeUps wakeUps, AtomicInteger running, boolean openToOutsideInvocations) {
        this.agents = agents;
        this.wakeUps = wakeUps;
        this.running = running;
        this.openToOutsideInvocations = openToOutsideInvocations;
    }

    /** Looks once (the mission's waiting thread, every period): true if this look and the last one agree on a deadlock. */
    boolean deadlocked() {
        long look = wakeUps.look();
        boolean idle = WakeUps.nonePending(look) && agents.stream().allMatch(Agent::isIdle)
                && !(openToOutsideInvocations && agents.stream().anyMatch(Agent::isParkedInBusyWait))
                && noAgentEnding()
                && look == wakeUps.look();
        boolean deadlocked = idle && lastLookIdle && look == lastIdleLook;
        lastLookIdle = idle;
        lastIdleLook = look;
        return deadlocked;
    }

    /**
     * Whether every agent whose program is over has been counted out: an agent is made DONE first
     * and counted out after (its report is built in between), so a DONE agent still counted as
     * running is ending, not idle. The states are read before the count, so a look that sees an
     * agent DONE sees the count as of then or later.
     */
    private boolean noAgentEnding() {
        long notDone = agents.stream().filter(agent -> !agent.isDone()).count();
        return running.get() == notDone;
    }
}
