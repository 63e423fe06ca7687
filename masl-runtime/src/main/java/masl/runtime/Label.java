package masl.runtime;

import java.util.concurrent.CompletableFuture;
import java.util.function.Consumer;
import masl.runtime.scheduling.ChangeEpoch;

/**
 * A MASL label (§10): collects invocations and tells when all have completed. {@code LLabel l;} is
 * one label per member (a local: {@code block$l = ctx.newLabel();}), {@code SLabel s;} one per wave
 * (a shared variable holding a label: {@code ctx.shared(S).initialise(ctx::newLabel)}).
 *
 * <p>Thread-safe: invocations complete on whichever thread serves them. A completion stores its
 * result (if the registration asked for it) <em>before</em> it is counted, so a program that saw
 * {@link #isFinished()} true reads every stored result. Completions advance the mission's change
 * epoch, so a busy-wait on {@code isFinished()} parks instead of spinning and wakes at the last one.
 *
 * <p><b>Memory consistency effects.</b> The store of a completion's result and its count happen-before
 * any read of the label ({@link #isFinished()}, {@link #getRemainingInvocations()}) that sees the count,
 * and so before what the program does after it (checked by the jcstress test
 * {@code LabelStoreBeforeCount}); a registration is never lost to a concurrent completion
 * ({@code LabelRegisterWhileCompleting}).
 *
 * <p>{@link #register} gives back a future that completes only once the completion is stored and
 * counted: a synchronous call awaits that one, so the instruction that made it ends with the
 * call done, counted and its result stored (§10), whichever thread served it.
 *
 * <p>A subclass is a view of a label another JVM's mission holds (a deployed agent's program, in its
 * container): each of its methods is then a request to that label, which alone counts.
 */
public class Label {

    private final ChangeEpoch changes;
    /** Registrations of the current generation not yet completed; guarded by {@code this}. */
    private int pending;
    /** Bumped by {@link #free()}: completions of earlier generations are ignored. */
    private long generation;

    /** A label whose completions advance {@code changes}, the mission's change epoch. */
    protected Label(ChangeEpoch changes) {
        this.changes = changes;
    }

    /**
     * {@code l.a.m(args)} (§10): registers {@code invocation}; an already completed one (an
     * internal synchronous primitive) counts as done at once. The future given back completes
     * with the invocation's value once the label has counted it.
     */
    public <T> CompletableFuture<T> register(CompletableFuture<T> invocation) {
        return register(invocation, value -> { });
    }

    /**
     * {@code l.x = a.m(args)}, {@code l.a.x = …}: registers {@code invocation}, and when it completes
     * (unless the label was freed meanwhile) passes its value to {@code store}, which assigns the
     * variable or attribute, on the completing thread. The future given back completes with the
     * invocation's value after the store and the count, so awaiting it (a synchronous primitive)
     * never sees the call done but not yet counted.
     */
    public <T> CompletableFuture<T> register(CompletableFuture<T> invocation, Consumer<? super T> store) {
        long registeredIn;
        synchronized (this) {
            pending++;
            registeredIn = generation;
        }
        return invocation.thenApply(value -> {
            completed(registeredIn, () -> store.accept(value));
            return value;
        });
    }

    /**
     * Counts a completion and runs its store. A store that fails (its owner's state is in a JVM that
     * is gone) still counts the call, so that no one waits for ever on {@link #isFinished}; the failure
     * completes the future {@link #register} gave back.
     */
    private void completed(long registeredIn, Runnable store) {
        RuntimeException failure = null;
        synchronized (this) {
            if (registeredIn != generation) {
                return;
            }
            pending--;
            try {
                store.run();
            } catch (RuntimeException e) {
                failure = e;
            }
        }
        changes.advance();
        if (failure != null) {
            throw failure;
        }
    }

    /** {@code l.isFinished()} / {@code isFinished(l)}: every registered invocation has completed. Zero duration. */
    public synchronized boolean isFinished() {
        return pending == 0;
    }

    /** {@code l.getRemainingInvocations()}: how many registered invocations have not completed yet. Zero duration. */
    public synchronized int getRemainingInvocations() {
        return pending;
    }

    /** {@code l.free()}: forgets the registered invocations; their completions are ignored. Zero duration. */
    public void free() {
        synchronized (this) {
            generation++;
            pending = 0;
        }
        changes.advance();
    }
}
