package masl.runtime.trace;

/**
 * One recorded change. {@code nanos} is {@link System#nanoTime()} when it happened; {@code agent}
 * is a proxy id; {@code block} an e-block's name; {@code event} a MASL event's name. {@code source},
 * in every record made where an agent's program stands at a statement, is that MASL statement as
 * {@link masl.runtime.AgentProgram#sourceAt} gives it ({@code "e6.masl:14: synchronous entry turn (…)"}),
 * or null when the program does not know it (hand-written programs).
 */
public sealed interface TraceEvent {

    long nanos();

    /** The MASL statement the agent stands at, for the records that have one; null otherwise. */
    default String source() {
        return null;
    }

    /**
     * The mission starts with these agents: {@code agents.get(id)} is the MASL name of the agent
     * whose proxy id is {@code id}. The first record of a trace.
     */
    record MissionStarted(long nanos, java.util.List<String> agents) implements TraceEvent {

        public MissionStarted {
            agents = java.util.List.copyOf(agents);
        }
    }

    /** The agent passed the test of an asynchronous or scalar block and is an active member. */
    record Entered(long nanos, int agent, String block, String source) implements TraceEvent { }

    /** The agent passed the test of a synchronous block and is held by its entry barrier. */
    record WaitingIn(long nanos, int agent, String block, String source) implements TraceEvent { }

    /** The entry barrier let the agent in: it is an active member of wave {@code wave}. */
    record Released(long nanos, int agent, String block, int wave, String source) implements TraceEvent { }

    /** The agent ran out of instructions of a synchronous block and is held by its exit barrier. */
    record WaitingOut(long nanos, int agent, String block, String source) implements TraceEvent { }

    /** The agent is no longer a member of the block. */
    record Left(long nanos, int agent, String block, LeaveCause cause, String source) implements TraceEvent { }

    /**
     * The synchronisation barrier of the barrier domain whose outermost block is {@code domain}
     * tripped, letting {@code agents} agents go on.
     */
    record BarrierTripped(long nanos, String domain, int agents) implements TraceEvent { }

    /** The block was empty and an arrival started its wave number {@code wave} (1, 2, …). */
    record WaveStarted(long nanos, String block, int wave) implements TraceEvent { }

    /** The last member of the wave left: the block is empty (§6.5). */
    record WaveEnded(long nanos, String block, int wave) implements TraceEvent { }

    /**
     * The agent emitted (or, for a system event, perceived) {@code event}, declared by {@code block}
     * ({@code null} for a system event), with {@code message} ({@code ""} if none); {@code receivers}
     * agents perceived it. Recorded before any receiver can react to it.
     */
    record EventEmitted(long nanos, int agent, String event, String block, String message, int receivers, String source)
            implements TraceEvent { }

    /**
     * The agent runs its reaction of block {@code block} to an occurrence of {@code event}:
     * {@code react(event)}, or {@code react(default)} if {@code byDefault}.
     */
    record EventReacted(long nanos, int agent, String event, String block, boolean byDefault, String source) implements TraceEvent { }

    /** The agent dropped an occurrence of {@code event}: no reaction to it in its blocks, or {@code clearEvents}. */
    record EventDropped(long nanos, int agent, String event, String source) implements TraceEvent { }

    /**
     * Agent {@code requester} queued an external invocation of primitive {@code member} of agent
     * {@code callee} (MASL §9).
     */
    record InvocationMade(long nanos, int requester, int callee, String member, String source) implements TraceEvent { }

    /**
     * Agent {@code callee} runs primitive {@code member} for {@code requester} ({@code -1}: a requester
     * outside the mission, such as a FIPA agent), permeability allowing it (§11).
     */
    record InvocationServed(long nanos, int callee, int requester, String member, String source) implements TraceEvent { }

    /**
     * Permeability state {@code state} of {@code callee} denied {@code requester} the invocation of
     * {@code member} (an internal one when both are the same agent): it did not run (§11).
     */
    record InvocationDenied(long nanos, int callee, int requester, String member, String state, String source)
            implements TraceEvent { }

    /**
     * {@code agent} left {@code block} while countermeasure {@code member} of agent {@code callee} was
     * armed there: the runtime launches it (§9). Recorded in firing order, innermost block first.
     */
    record CountermeasureFired(long nanos, int agent, int callee, String member, String block, String source)
            implements TraceEvent { }

    /**
     * The agent's program stopped for good: {@code cause} (the class name and message of what it
     * threw) escaped from it at {@code source}. The agent leaves every block it was in (records
     * {@code left} with cause {@code failed} follow) and the other agents go on.
     */
    record AgentFailed(long nanos, int agent, String cause, String source) implements TraceEvent { }

    /**
     * The mission ended with {@code status} ({@code completed}, {@code failed}, {@code deadlocked},
     * {@code timed_out}, {@code stopped}): the last record of a trace. {@code reason} says why a
     * stopped mission was stopped (a signal, a journal that cannot be written), or is null.
     */
    record MissionEnded(long nanos, String status, String reason) implements TraceEvent {

        public MissionEnded(long nanos, String status) {
            this(nanos, status, null);
        }
    }
}
