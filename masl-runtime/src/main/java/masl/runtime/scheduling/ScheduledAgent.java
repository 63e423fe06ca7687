package masl.runtime.scheduling;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import masl.runtime.AgentProgram;
import masl.runtime.Mission;

/**
 * The scheduling side of an agent ({@code masl.runtime.Agent}): its {@link RunState}, the layer it
 * extends, the park in progress and its kind, the bookkeeping of the current slice and the
 * statement the agent is at. The layers of an agent are superclasses, each of its package (the run
 * state, this one, then {@code entry.MemberAgent}, {@code event.ReactingAgent}, {@code invocation.ServingAgent}, then the
 * boundaries that tie them, {@code SteppingAgent}, under {@code Agent} itself), not
 * objects it points to: an agent-step in lock-step reads fields of all of them, and one object
 * keeps them in the cache lines of one object, with no load of another's address on the way.
 *
 * <p><b>Parking.</b> A runtime call that must wait takes a ticket ({@link #prepareToPark()}) and
 * makes its caller, the program, return; whoever ends the wait calls {@link #unpark(long)} with it,
 * which schedules the agent again. A stale or repeated ticket does nothing.
 *
 * <p><b>Memory consistency effects.</b> Those of {@link RunState}: actions of the agent's slice
 * before it takes a ticket happen-before the actions of a thread that {@linkplain #unpark unparks}
 * it with that ticket, and actions of that thread before the unpark happen-before the slice the
 * scheduler then runs. The fields of the slice's bookkeeping are confined to the agent's slices,
 * which the run state orders one after the other.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public abstract class ScheduledAgent extends RunState implements AgentTask {

    protected final int id;
    protected final String name;
    protected final AgentProgram program;
    protected final Mission mission;
    /** The scheduler's {@link Scheduler#stepsPerSlice}, read once: every boundary compares with it. */
    private final int stepsPerSlice;
    protected volatile boolean finished;
    /** Whether the agent's latest park is a busy-wait's: for the deadlock watchdog (Mission). */
    protected volatile boolean busyWaitPark;

    // Confined to the thread running the current slice (successive slices are ordered).
    protected boolean suspended;
    protected int stepsThisSlice;
    /** Step boundaries and plain loop iterations passed: "ran an instruction" for busy-waits. */
    protected long progress;
    /** The program's pc was set to other code: resume it at once, in this slice. */
    protected boolean redirected;
    /**
     * The resumption point whose MASL statement the agent is at, for trace records and reports: the
     * case making the current runtime call. A suspending call comes after {@code pc} was set to the
     * case that follows it (the contract numbers cases in program order), a loop iteration or a call
     * in the middle of a case finds {@code pc} at its own case. Read by others only while parked.
     */
    protected int statementPc;
    /** Whether {@link #statementPc} is a loop's head, whose statement is the loop, not the last one of its body. */
    protected boolean statementIsLoop;
    /** Whether the latest park is a {@code wait(state)}'s, the only one that makes the agent attentive. */
    protected boolean parkAttends;
    /** Whether the latest park waits for a step that goes on elsewhere ({@link #awaitElsewhere}): it ends {@code AWAY}. */
    protected boolean awayPark;
    /** Told when the agent's next boundary has work (an event, an invocation), or null: see {@link #onBoundaryWork}. */
    private volatile Runnable boundaryWork;

    protected ScheduledAgent(int id, String name, AgentProgram program, Mission mission) {
        this.id = id;
        this.name = name;
        this.program = program;
        this.mission = mission;
        this.stepsPerSlice = mission.scheduler().stepsPerSlice();
    }

    @Override
    public final int id() {
        return id;
    }

    /** The agent, where it is in its program, for error messages. */
    @Override
    public abstract String describe();

    @Override
    protected final void countWakeUp() {
        mission.countSchedule();
    }

    /**
     * The MASL statement the agent is at ({@code "e6.masl:14: synchronous entry turn (…)"}), or null
     * if its program does not say.
     */
    public abstract String source();

    /** Whether the mission's end is decided, or it failed for want of memory: then no agent goes on. */
    protected abstract boolean halted();

    /** Issues the ticket of a park: the caller (this agent's own slice) then returns {@code false}. */
    public final long prepareToPark() {
        if (suspended) {
            throw new IllegalStateException(describe() + ": runtime called again after a suspension");
        }
        suspended = true;
        // A volatile write costs a fence; in lock-step no park is a busy-wait's, and this reads it.
        if (busyWaitPark) {
            busyWaitPark = false;
        }
        parkAttends = false;
        awayPark = false;
        return issueTicket();
    }

    /**
     * Takes back the park that issued {@code ticket}, which nobody has ended: the call that issued
     * it goes on without waiting after all (the arrival that completes a synchronisation barrier).
     */
    public final void cancelPark(long ticket) {
        if (!takeBack(ticket)) {
            throw new IllegalStateException(describe() + ": its park was ended before it was taken back");
        }
        suspended = false;
    }

    /** Ends the park that issued {@code ticket}; ignored if that park already ended. */
    public final void unpark(long ticket) {
        if (ticket != 0 && pendingTicket() == ticket) {
            // Counted before the agent leaves PARKED, for the deadlock watchdog (Mission). Another
            // thread may end the park first: one count too many only puts the watchdog's verdict off.
            mission.countSchedule();
            if (endPark(ticket)) {
                mission.scheduler().schedule(this);
            }
        }
    }

    /** Parked in a busy-wait: waiting for a change, which an outside invocation is. */
    public final boolean isParkedInBusyWait() {
        return isParked() && busyWaitPark;
    }

    /** {@code sleep(ms)} (AgentContext): parks the agent until {@code ms} have passed. */
    public final boolean sleep(long ms) {
        atCallBefore();
        progress++;
        if (ms <= 0) {
            return yieldIfSliceUsed();
        }
        long ticket = prepareToPark();
        mission.outsideWakeUpStarted();
        mission.scheduler().scheduleAfter(ms, () -> {
            unpark(ticket);
            mission.outsideWakeUpEnded();
        });
        return false;
    }

    /** Parks the agent until {@code result} is complete (AgentContext). */
    public final boolean await(CompletionStage<?> result) {
        atCallBefore();
        CompletableFuture<?> future = result.toCompletableFuture();
        if (future.isDone()) {
            return yieldIfSliceUsed();
        }
        long ticket = prepareToPark();
        mission.outsideWakeUpStarted();
        future.whenComplete((value, failure) -> {
            unpark(ticket);
            mission.outsideWakeUpEnded();
        });
        return false;
    }

    /**
     * Parks the agent while its step goes on elsewhere (a deployed agent's, in its container) until
     * {@link #unpark} with the ticket returned, once the step's next message has come: its thread is
     * free meanwhile and it is not blocked ({@link RunState}, {@code AWAY}), so no invocation is
     * served on its behalf, and the deadlock watchdog counts it running. Not a call of the program,
     * unlike {@link #await}: no statement, progress or step of the slice is counted. The caller
     * returns from the program's {@code resume}, which the next slice calls again. 0, and nothing
     * done, if the slice has parked already or the program has finished (a call performed for the
     * step did): the caller must then wait on its thread. Called by the agent's slice.
     */
    public final long awaitElsewhere() {
        if (suspended || finished) {
            return 0;
        }
        long ticket = prepareToPark();
        awayPark = true;
        return ticket;
    }

    /**
     * Has {@code hook} run, on the thread that brings it, each time something arrives that the
     * agent's next boundary must act on (an occurrence perceived, an invocation queued): a program
     * that runs elsewhere (a deployed agent's) passes its boundaries there while nothing does.
     */
    public final void onBoundaryWork(Runnable hook) {
        boundaryWork = hook;
    }

    /** Something arrived that the agent's next boundary acts on: its flag is set already. */
    protected final void boundaryWorkArrived() {
        Runnable hook = boundaryWork;
        if (hook != null) {
            hook.run();
        }
    }

    /** Its program is over: no slice runs it again. */
    protected final void end() {
        finished = true;
        done();
    }

    /** Counts a step of the slice; at the slice's end, parks the agent and wakes it at once (the scheduler's turn). */
    protected final boolean yieldIfSliceUsed() {
        if (++stepsThisSlice < stepsPerSlice && !halted()) {
            return true;
        }
        long ticket = prepareToPark();
        if (!halted()) {
            unpark(ticket);
        }
        // else parked for good: the mission has ended, or failed for want of memory, which this agent would take
        return false;
    }

    /** The current runtime call comes after {@code pc} was set to the case that follows its own. */
    protected final void atCallBefore() {
        statementPc = program.pc() - 1;
        statementIsLoop = false;
    }

    /** The current runtime call is made from the case {@code pc} names. */
    protected final void atCurrentCase() {
        statementPc = program.pc();
        statementIsLoop = false;
    }

    /** The current runtime call is a loop's iteration, made from its head, the case {@code pc} names. */
    protected final void atLoopHead() {
        statementPc = program.pc();
        statementIsLoop = true;
    }

    @Override
    public String toString() {
        return name;
    }
}
