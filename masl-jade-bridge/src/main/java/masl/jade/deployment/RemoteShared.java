package masl.jade.deployment;

import java.util.function.Supplier;
import java.util.function.UnaryOperator;
import masl.runtime.SharedDeclaration;
import masl.runtime.SharedVariable;
import masl.runtime.scheduling.ChangeEpoch;

/**
 * A shared variable as a deployed agent's program sees it: every read and write is a request to the
 * mission, which owns the wave's copy; an update's function and the initialiser run here, in the step
 * that waits for the mission's answer, asked by the mission while it holds the variable's lock, so that
 * no other write comes in between, as in-process; the requests they make (an initialiser's {@code
 * main.count}) nest in the one the step waits for. An array read is the mission's array as it was
 * then, a copy; a store into one of its elements, which the program made in that copy, is sent to the
 * mission, which stores the element in its own array.
 */
final class RemoteShared<T> extends SharedVariable<T> {

    private final SharedDeclaration<T> declaration;
    private final RemoteContext context;

    RemoteShared(SharedDeclaration<T> declaration, RemoteContext context) {
        super(declaration, new ChangeEpoch());
        this.declaration = declaration;
        this.context = context;
    }

    @Override
    @SuppressWarnings("unchecked")
    public void initialise(Supplier<? extends T> initialiser) {
        context.sharedCall("initialise", declaration, ignored -> initialiser.get(), null);
    }

    @Override
    @SuppressWarnings("unchecked")
    public T get() {
        return (T) context.sharedCall("get", declaration, null, null);
    }

    @Override
    public void set(T newValue) {
        context.sharedCall("set", declaration, null, newValue);
    }

    @Override
    @SuppressWarnings("unchecked")
    public T update(UnaryOperator<T> function) {
        return (T) context.sharedCall("update", declaration, value -> function.apply((T) value), null);
    }

    @Override
    @SuppressWarnings("unchecked")
    public T getAndUpdate(UnaryOperator<T> function) {
        return (T) context.sharedCall("getAndUpdate", declaration, value -> function.apply((T) value), null);
    }

    @Override
    public <E> E stored(E element, int index) {
        context.storeElement(declaration, element, index);
        return element;
    }

    @Override
    public <E> E stored(E element, int index, int... inner) {
        context.storeElement(declaration, element, path(index, inner));
        return element;
    }

    @Override
    public <E> E postfixStored(E before, E element, int index, int... inner) {
        context.storeElement(declaration, element, path(index, inner));
        return before;
    }

    private static int[] path(int index, int... inner) {
        int[] path = new int[inner.length + 1];
        path[0] = index;
        System.arraycopy(inner, 0, path, 1, inner.length);
        return path;
    }
}
