package masl.runtime.testing;

import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.ESequence;
import masl.runtime.EntryDefinition;

/**
 * The generated-code contract in a shorter notation for test programs: each helper sets {@code pc}
 * exactly as the contract says, makes the one runtime call, and returns what the program must do
 * next: {@code true} continue the dispatch loop (at the new {@code pc}), {@code false} return. A
 * case then reads {@code if (!step(ctx, 5)) return; continue;}.
 */
public abstract class CompactProgram extends AgentProgram {

    protected final TestAgent self;

    protected CompactProgram(TestAgent self) {
        this.self = self;
    }

    /** Arrival at {@code block}: continue at {@code body} if a member, at {@code after} if skipped. */
    protected final boolean arrive(AgentContext ctx, EntryDefinition block, boolean test, int body, int after) {
        pc = body;
        switch (ctx.enter(block, test)) {
            case SKIPPED -> {
                pc = after;
                return true;
            }
            case WAITING -> {
                return false;
            }
            default -> {
                return true;
            }
        }
    }

    /** The step boundary after an instruction; continue at {@code next}. */
    protected final boolean step(AgentContext ctx, int next) {
        pc = next;
        return ctx.stepBoundary();
    }

    /** Normal end of {@code block}; continue at {@code next}. */
    protected final boolean leave(AgentContext ctx, EntryDefinition block, int next) {
        pc = next;
        return ctx.leave(block);
    }

    /**
     * End of an asynchronous or scalar child of a synchronous block, one instruction of it (§6.4):
     * the parent's barrier; continue at {@code next}. Where the child ends its e-sequence, test
     * programs without events or invocations let this stand for the e-sequence's end too (a step
     * boundary without barrier, which has nothing to do for them).
     */
    protected final boolean endOfChild(AgentContext ctx, EntryDefinition child, int next) {
        pc = next;
        return ctx.endOfChild(child);
    }

    /** End of an e-sequence; continue at {@code next}. */
    protected final boolean endOf(AgentContext ctx, ESequence sequence, int next) {
        pc = next;
        return ctx.endOfSequence(sequence);
    }

    /** A busy-wait loop: continue at {@code loopEnd} when {@code waiting} is false, else iterate at the current pc. */
    protected final boolean busyWait(AgentContext ctx, boolean waiting, int loopEnd) {
        if (!waiting) {
            pc = loopEnd;
            return true;
        }
        return ctx.busyWaitIteration();
    }

    /** A loop's iteration that never parks; continue at {@code head}. */
    protected final boolean loop(AgentContext ctx, int head) {
        pc = head;
        return ctx.loopIteration();
    }

    /** {@code resume} ending a reaction: on to the next reaction, or back where the boundary was. */
    protected final boolean resumeAfterReaction(AgentContext ctx) {
        return ctx.endReaction() && ctx.resumeInterrupted();
    }

    /**
     * {@code break} ending a reaction, or its end without an ending statement: if it is the last
     * reaction, leaves {@code block} and continues at {@code after}, the instruction after it.
     */
    protected final boolean breakAfterReaction(AgentContext ctx, EntryDefinition block, int after) {
        if (!ctx.endReaction()) {
            return false;
        }
        ctx.breakOut(block);
        pc = after;
        return true;
    }
}
