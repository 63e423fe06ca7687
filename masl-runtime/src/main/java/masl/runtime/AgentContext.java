package masl.runtime;

import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.function.Supplier;
import masl.runtime.entry.Entry;

/**
 * What a generated program calls on the runtime: one instance per agent, passed to
 * {@link AgentProgram#resume}. The full contract, with a worked example, is
 * {@code masl-runtime/docs/generated-code-contract.md}.
 *
 * <p><b>Suspension protocol.</b> A method returning {@code boolean} may suspend the agent. Before
 * calling it the program sets {@code pc} to the point to continue at. {@code true} means "go on
 * now" (fall through to that point); {@code false} means the agent is suspended: the program must
 * return from {@code resume} at once, without calling the runtime again, and will be resumed at
 * {@code pc} once the wait is over (barrier tripped, agent released, time elapsed, change seen).
 * A program that returns without a suspension or {@link #finish()} is a contract violation that
 * fails the mission.
 *
 * <p>Every method must be called from within {@code resume} of this context's agent.
 */
public interface AgentContext {

    /** The agent's proxy id: 0, 1, 2, … in declaration order. */
    int proxyId();

    /**
     * The step boundary after an instruction of non-zero duration (MASL §5): (1) events, (2)
     * pending external invocations, (3) the synchronisation barrier if the innermost block is
     * synchronous. May also return {@code false} merely to let other agents run (a yield), or
     * because the runtime redirected the program to a reaction (§8): the program returns either way.
     * Every boundary below processes events the same way.
     */
    boolean stepBoundary();

    /**
     * The end of an iteration of a loop that may change state the runtime cannot see (its body or
     * update changes locals, its condition calls a primitive or Java method): steps 1 and 2 of the
     * step boundary, no barrier, never parks; may yield.
     */
    boolean loopIteration();

    /**
     * The end of an iteration of a busy-wait loop: a loop whose condition and body observe only
     * state the runtime sees (shared variables, entry members, labels, events, invocations, and
     * locals the loop does not change). Steps 1 and 2 of the step boundary; then, if nothing the
     * agent can observe changed and it ran no instruction since its previous busy-wait
     * iteration, the agent parks until something changes, instead of spinning (§5).
     */
    boolean busyWaitIteration();

    /**
     * Arrival at an e-block, after its test was evaluated (zero duration). The agent must be an
     * active member of the block's parent, with no block of the parent's body entered (it is at
     * the parent's instruction level). Before the call, set {@code pc} to the block's first
     * instruction (its declarations).
     */
    Arrival enter(EntryDefinition block, boolean test);

    /**
     * Normal end of the innermost block. Asynchronous and scalar blocks are left at once;
     * synchronous ones after the exit barrier (§6.3). Before the call set {@code pc} to the
     * instruction after the block (the test of the next block of its e-sequence, or the end of
     * the e-sequence).
     */
    boolean leave(EntryDefinition block);

    /**
     * The end of an asynchronous or scalar child of a synchronous block (§6.4): one instruction for
     * every active member of the parent, whether it ran the child, was not the one elected to run a
     * scalar child, skipped it, or left it by {@code break} or a reaction. The agent reaches the
     * parent's synchronisation barrier here, before anyone tests the next block of the e-sequence.
     * The translator calls it after each such child, and only there; before the call set {@code pc}
     * to the instruction after the block.
     */
    boolean endOfChild(EntryDefinition block);

    /**
     * The end of an e-sequence in the body of a block, or of the top-level one: a step boundary
     * without barrier (events and invocations). The barrier points of a synchronous parent are the
     * instructions of its synchronous children and the end of each asynchronous or scalar child
     * ({@link #endOfChild}); a member that skips a synchronous child does not wait for it (§6.4).
     * Before the call set {@code pc} to the instruction after the e-sequence.
     */
    boolean endOfSequence(ESequence sequence);

    /**
     * {@code break(…)}: leaves every block from the innermost to {@code outermost} inclusive, with
     * no exit barrier. The program then continues after {@code outermost}: set {@code pc} to the
     * instruction after that block and continue.
     */
    void breakOut(EntryDefinition outermost);

    /**
     * {@code reelect(…)}: leaves every block from the innermost to {@code block} inclusive, with
     * no exit barrier. The program then arrives at {@code block} again: jump to its test, and
     * keep (do not re-initialise) its locals if the new arrival enters.
     */
    void reelect(EntryDefinition block);

    /**
     * {@code restart}: leaves the blocks nested in {@code block} (if any), which stays the
     * innermost block. The program then jumps to the first instruction after its declarations.
     */
    void restart(EntryDefinition block);

    /** This wave's copy of a shared variable of the innermost block or of one of its ancestors. */
    <T> SharedVariable<T> shared(SharedDeclaration<T> declaration);

    /** The mission state of a block, for entry members (§6.7): {@code e.count}, {@code e.release()}, … */
    Entry entry(EntryDefinition block);

    /**
     * {@code .sleep(ms)} and {@code Thread.sleep(ms)} as statements (§12): a timed suspension on
     * the mission clock. Returns {@code false} (suspends) unless {@code ms <= 0}.
     */
    boolean sleep(long ms);

    /**
     * Waits for {@code result} without holding a thread: a blocking (synchronous) invocation, the
     * read of a variable holding a future (§9). Returns {@code true} if it is already complete;
     * otherwise suspends, and the agent is resumed at {@code pc} once it is complete. Either way
     * the program then reads it with {@code join()} (or {@code getNow}).
     */
    boolean await(CompletionStage<?> result);

    /**
     * {@code emit(e)} / {@code emit e} (MASL §8): as {@link #emit(Event, String)} with the message
     * {@code ""}.
     */
    void emit(Event event);

    /**
     * {@code emitWithMessage(e, text)} (MASL §8): every member of {@code event}'s block perceives
     * an occurrence at once (the emitter too) if the event is shared; only the emitter if it is
     * local or a system event. Never blocks: the receivers react at their next step boundary or
     * loop iteration; a receiver parked in a busy-wait is woken. Costs one push per receiver.
     *
     * @throws IllegalStateException if the agent is not a member of the event's block (a
     *     translator bug: emitting from outside the block is a compile error)
     */
    void emit(Event event, String message);

    /**
     * A primitive or Java call threw {@code thrown} (MASL §8, §9): the agent perceives
     * {@code uncaught_exception} with the exception's class name as message. The program then goes
     * on with the call's value being the type's default.
     */
    void uncaughtException(Throwable thrown);

    /**
     * {@code getMessageFromEvent(e)} in a reaction: the message of the occurrence being reacted to
     * if it is an occurrence of {@code event}; {@code null} otherwise (no occurrence of it is being
     * handled). Zero duration.
     */
    String messageOf(Event event);

    /**
     * The end of a reaction's statements (MASL §8), reached by its ending statement ({@code resume},
     * {@code break…}, {@code restart}, {@code reelect…}) or by the end of its body. {@code false}:
     * more reactions follow; the runtime has set {@code pc} to the next one's code, and the program
     * returns at once. {@code true}: this was the last reaction, which decides: the program applies
     * its ending now, with {@link #resumeInterrupted()}, {@link #breakOut}, {@link #restart} or
     * {@link #reelect}, exactly as the same statement in the body of the reaction's block (a
     * reaction that ends without one leaves its block: {@code breakOut} of that block).
     */
    boolean endReaction();

    /**
     * {@code resume} as the ending of the last reaction: sets {@code pc} to where the interrupted
     * step boundary or loop iteration was to continue, and completes that boundary (pending
     * invocations, then the barrier if it was a step boundary in a synchronous block). The program
     * then {@code continue}s its dispatch loop on {@code true} and returns on {@code false}, as for
     * any suspension.
     */
    boolean resumeInterrupted();

    /**
     * {@code clearEvents} in a reaction (MASL §8): drops the occurrences not yet reacted to, those
     * of this processing and those perceived since, so that the current reaction decides.
     */
    void clearEvents();

    /**
     * The agent's program is over: it has left {@code main}, or skipped it, or the program has no
     * {@code main}. The program must return right after. The agent stays alive to serve
     * invocations; the mission ends when every agent has finished.
     */
    void finish();

    // ---- invocations, attributes and permeability (MASL §9, §11) ------------------------------

    /**
     * An external invocation {@code a.m(args)} (MASL §9): queues it at {@code callee}, which runs
     * {@code call} at its next step boundary or loop iteration, or at once on its behalf if it is
     * blocked or has finished (§5). Never blocks: a synchronous primitive is then awaited with
     * {@link #await} and read with {@code join()}. The future always completes normally: with the
     * primitive's result; with {@code defaultValue} if the primitive threw (this agent perceives
     * {@code uncaught_exception}, message the exception's class name) or if the callee's
     * permeability denied it when it came to serve it (this agent perceives {@code timeout},
     * message the primitive's name, and the primitive does not run). When {@code callee} is this
     * agent the invocation is internal and runs now, as {@link #invokeSelf}.
     * A {@code null} callee (an agent variable holding no agent) makes this agent perceive
     * {@code uncaught_exception} ({@code java.lang.NullPointerException}) and gives the default
     * value; so do the other calls taking an agent here.
     *
     * @param primitive the primitive's name in the callee's descriptor: permeability filters by it
     * @param call runs the primitive on the callee's implementation object; it runs on the thread
     *     serving the callee and must use nothing of this agent's program but what it captured
     * @throws IllegalArgumentException if {@code callee} runs no agent of this mission
     */
    <T> CompletableFuture<T> invoke(AgentImplementation callee, String primitive, T defaultValue, Callable<T> call);

    /**
     * An internal invocation {@code .m(args)} (MASL §9): runs {@code call} now, if the current
     * permeability state lets the agent invoke its own {@code primitive} (the u digit, §11), and
     * returns its result. Denied, it returns {@code defaultValue} and the agent perceives
     * {@code timeout}; if the primitive throws, {@code defaultValue} and {@code uncaught_exception}.
     * Zero duration itself: the program adds the step boundary unless the primitive is an accessor.
     */
    <T> T invokeSelf(String primitive, T defaultValue, Callable<T> call);

    /**
     * A read of attribute {@code attribute} of {@code owner} (this agent's own implementation for
     * {@code x} / {@code this.x}), immediate and subject to permeability (§9, §11): the r bit of the
     * requester's digit in the owner's current state. Denied, it returns {@code defaultValue} and the
     * agent perceives {@code forbidden_access} (message: the attribute's name). Zero duration.
     */
    <T> T readAttribute(AgentImplementation owner, String attribute, T defaultValue, Supplier<T> read);

    /**
     * A write of attribute {@code attribute} of {@code owner}, as {@link #readAttribute} with the w
     * bit: denied, {@code write} does not run and the agent perceives {@code forbidden_access}.
     * Returns whether it ran.
     */
    boolean writeAttribute(AgentImplementation owner, String attribute, Runnable write);

    /**
     * {@code setAcceptState("name")} (§11): the agent's current permeability state becomes the
     * type's state {@code name}; invocations served from now on are filtered by it, and busy-waits
     * reading accept states see the change. An undeclared name changes nothing and makes the agent
     * perceive {@code uncaught_exception} ({@code java.lang.IllegalArgumentException}).
     */
    void setAcceptState(String name);

    /** {@code getAcceptState()}: the current state's name; {@code ""} for a type without states. */
    String getAcceptState();

    /** {@code getAcceptState(a)}: agent {@code a}'s current state's name, read now. */
    String getAcceptState(AgentImplementation agent);

    /**
     * {@code wait("state")} (§11): the agent becomes attentive until the first pending or arriving
     * external invocation that {@code state} allows for its requester has run, as this
     * instruction; the other pending invocations stay queued, to be served at the next step
     * boundary by the current state. Suspends unless such an invocation is already pending (then
     * it runs now). An undeclared state raises {@code uncaught_exception} and ends the wait at once.
     * The program then adds the instruction's step boundary.
     */
    boolean waitFor(String state);

    /**
     * {@code wait("state", ms)}: as {@link #waitFor(String)}, also ending when {@code ms} of mission
     * time have elapsed with no allowed invocation.
     */
    boolean waitFor(String state, long ms);

    // ---- asynchronous primitives, countermeasures and labels (MASL §9, §10) -------------------

    /**
     * The invocation of an asynchronous primitive ({@code synchronous_call="false"}), internal or
     * external: returns at once. Internal, it is filtered by permeability now; external, it is
     * queued and filtered when the callee serves it (§5, §11), as {@link #invoke}. Allowed, its Java
     * code {@code call} runs on a thread of its own; the future completes with its result, or with
     * {@code defaultValue} on an exception ({@code uncaught_exception} here) or a denial
     * ({@code timeout} here). Reading a variable holding it awaits it ({@link #await}).
     */
    <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue, Callable<T> call);

    /**
     * {@link #launch(AgentImplementation, String, Object, Callable)} of a primitive with a
     * countermeasure (§9): also arms {@code countermeasure} of {@code callee}, whose Java code is
     * {@code countermeasureCall}, for the agent's innermost block. When the agent leaves that block
     * in any way ({@link #leave}, {@link #breakOut}, {@link #reelect}, {@link #restart} of an
     * enclosing block, also from a reaction) while it is armed, the runtime launches it, innermost
     * blocks first and the latest armed first within a block, before leaving (before an exit
     * barrier), and completes this launch's future with {@code defaultValue} if it is still
     * running. Invoking {@code countermeasure} of {@code callee} explicitly ({@link #invoke},
     * {@link #invokeSelf}, {@code launch}) disarms it.
     */
    <T> CompletableFuture<T> launch(AgentImplementation callee, String primitive, T defaultValue, Callable<T> call,
            String countermeasure, Callable<?> countermeasureCall);

    /** A new label ({@code LLabel}: one per member; {@code SLabel}: as the value of a shared variable), §10. */
    Label newLabel();
}
