package masl.runtime.trace;

/** Why an agent left a block (MASL §6.5). */
public enum LeaveCause {
    /** It ran out of instructions (after the exit barrier, in a synchronous block). */
    END,
    /** {@code break}, {@code break(n)} or {@code break(name)}. */
    BREAK,
    /** {@code reelect}: it leaves and arrives at the block again. */
    REELECT,
    /** {@code restart} of an enclosing block left this inner one. */
    RESTART,
    /** Its program threw: the agent left every block it was in (record {@code agent-failed}). */
    FAILED
}
