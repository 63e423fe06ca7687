package masl.runtime;

/** What became of an agent that arrived at an e-block: the result of {@link AgentContext#enter}. */
public enum Arrival {
    /** It is an active member: the program goes on with the block's first instruction, now. */
    ENTERED,
    /**
     * It is a member held by the entry barrier (synchronous blocks only): the program returns; it
     * is resumed, at the pc it set before the call, once the barrier has let it in.
     */
    WAITING,
    /**
     * It is not a member: its test was false, or another agent runs this scalar block in the
     * current wave of the parent. The program goes on with the instruction after the block.
     */
    SKIPPED
}
