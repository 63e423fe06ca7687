package masl.runtime;

import java.util.function.Supplier;
import java.util.function.UnaryOperator;
import masl.runtime.scheduling.ChangeEpoch;

/**
 * One wave's copy of a shared variable (MASL §7).
 *
 * <p>Reads are plain volatile reads. Every write, and every read-modify-write
 * ({@code x++}, {@code x op= e}, {@code x = f(x)}), holds this variable's monitor while it
 * computes and stores the new value, so no other write to the variable comes in between. Each
 * write advances the mission's change epoch, which wakes agents parked in a busy-wait loop (§5).
 *
 * <p>Not final for one subclass only: the copy a deployed agent's program uses in another JVM (the JADE
 * bridge's), each of whose methods is a request to the mission's own copy.
 *
 * @param <T> the variable's (boxed) Java type
 */
public class SharedVariable<T> {

    private final SharedDeclaration<T> declaration;
    private final ChangeEpoch changes;
    private volatile T value;
    private volatile boolean initialised;

    /** <b>Internal:</b> not part of the API. */
    public SharedVariable(SharedDeclaration<T> declaration, ChangeEpoch changes) {
        this.declaration = declaration;
        this.changes = changes;
        this.value = declaration.initialValue();
    }

    /**
     * Runs the declaration's initialiser if no member of this wave has run it yet. Every member
     * calls this when it executes the declaration; the first one evaluates {@code initialiser},
     * the others wait until it has stored the value, so no member can read the variable before it
     * is initialised. Initialisation is not a change observed by busy-wait loops: it happens
     * before any member reads.
     */
    public void initialise(Supplier<? extends T> initialiser) {
        if (initialised) {
            return;
        }
        synchronized (this) {
            if (!initialised) {
                value = initialiser.get();
                initialised = true;
            }
        }
    }

    /** Plain read, not locked (§7). */
    public T get() {
        return value;
    }

    /** Plain assignment {@code x = v}. */
    public void set(T newValue) {
        synchronized (this) {
            value = newValue;
        }
        changes.advance();
    }

    /** Atomic {@code x = f(x)}, {@code ++x}, {@code x op= e}: returns the new value. */
    public T update(UnaryOperator<T> function) {
        T updated;
        synchronized (this) {
            updated = function.apply(value);
            value = updated;
        }
        changes.advance();
        return updated;
    }

    /** Atomic {@code x++}, {@code x--}: returns the value before the update. */
    public T getAndUpdate(UnaryOperator<T> function) {
        T previous;
        synchronized (this) {
            previous = value;
            value = function.apply(previous);
        }
        changes.advance();
        return previous;
    }

    /**
     * {@code a[i] = e}, {@code a[i] op= e}, {@code ++a[i]}, {@code a[i]++} as an instruction: the program
     * has just stored {@code element} at {@code index} of the array {@link #get} gave it, as Java does;
     * returns {@code element}, the assignment's value. Here that array is this variable's own: the store
     * is Java's, no more atomic than there (MASL §7 locks writes of the variable, not of its elements),
     * and only wakes the agents whose busy-wait loops may be waiting for it (§5). A deployed agent's
     * copy of the variable (the JADE bridge's) has the element stored in the mission's array, the owner's.
     */
    public <E> E stored(E element, int index) {
        changes.advance();
        return element;
    }

    /** As {@link #stored(Object, int)} for an element of a nested array: {@code a[index][inner[0]]…}. */
    public <E> E stored(E element, int index, int... inner) {
        changes.advance();
        return element;
    }

    /**
     * {@code a[i]++}, {@code a[i]--} inside an expression, as {@link #stored(Object, int, int...)}:
     * {@code element} is the element stored, {@code before} the one it replaced, the expression's value,
     * returned.
     */
    public <E> E postfixStored(E before, E element, int index, int... inner) {
        changes.advance();
        return before;
    }

    @Override
    public String toString() {
        return declaration.name() + "=" + value;
    }
}
