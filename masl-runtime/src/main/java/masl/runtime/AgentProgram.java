package masl.runtime;

/**
 * An agent's program as a resumable state machine (components.md, "Execution model"); the
 * translator generates one subclass per agent type, and docs/generated-code-contract.md says how.
 *
 * <p>The program's locals are fields of the subclass; {@link #pc} names the point to resume at.
 * The runtime calls {@link #resume} whenever the agent is runnable, never from two threads at
 * once, and each call happens-after the previous one returned. The program runs until a runtime
 * call returns {@code false}, and then returns at once; or until it calls
 * {@link AgentContext#finish()} and returns.
 */
public abstract class AgentProgram {

    /** The resumption point: 0 at start, then whatever the program set before it returned. */
    protected int pc;

    /** Runs the program from {@link #pc} until it must wait or has finished. */
    protected abstract void resume(AgentContext ctx);

    /**
     * Where the code of {@code reaction} starts: the {@code case} the runtime sets {@code pc} to when
     * the agent is to run that reaction (docs/generated-code-contract.md, "Events and reactions").
     * A program whose blocks have reactions overrides this; the default says there are none.
     *
     * @throws IllegalArgumentException if this program has no code for {@code reaction}
     */
    protected int reactionPc(Reaction reaction) {
        throw new IllegalArgumentException(getClass().getName() + " has no code for " + reaction);
    }

    /** Sets the resumption point from the runtime's side: event processing redirects the program. */
    final void jump(int resumptionPoint) {
        pc = resumptionPoint;
    }

    /**
     * The MASL source of resumption point {@code pc} ({@code "hello.masl:5: .logln(x);"}), or null when
     * unknown: reports of a deadlock or a failure name each agent's place in the program, not in
     * generated code. Generated programs override it.
     */
    protected String sourceAt(int pc) {
        return null;
    }

    /**
     * The MASL source of the statement whose runtime call ends the case of resumption point {@code pc}:
     * the last statement written in it, where {@link #sourceAt} gives the first (an {@code else}
     * followed by {@code .logln(x);}). The trace and reports name a suspended agent's statement so.
     */
    protected String sourceOfCallIn(int pc) {
        return sourceAt(pc);
    }

    /** The current resumption point, for diagnostics. */
    public final int pc() {
        return pc;
    }
}
