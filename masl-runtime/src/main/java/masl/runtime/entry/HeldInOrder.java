package masl.runtime.entry;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * The agents an entry or exit barrier holds, in arrival order (MASL §6.3): appended as they
 * arrive, let go from the first, and removed from anywhere when one dies while held, each in
 * O(1). A list would make a removal scan the held agents, and a wave whose members die one by one
 * while the others wait out (a lost container's deployed agents, a program that fails) would
 * then cost the square of its size. Iteration, {@link #poll} and {@link #toList} follow arrival
 * order, as a list's would: an element removed keeps the others' order, one added again goes last.
 *
 * <p>Not thread-safe: guarded by the {@link EntryCoordinator}'s lock, like the waves and entries
 * that hold it. Generic for its test, which counts the comparisons it makes.
 *
 * @param <T> the held elements: agents; each held at most once
 */
final class HeldInOrder<T> implements Iterable<T> {

    private final Set<T> held = new LinkedHashSet<>();

    /** Holds {@code element} after every other; it must not be held already. */
    void add(T element) {
        if (!held.add(element)) {
            throw new IllegalStateException(element + " is held already");
        }
    }

    /** Lets {@code element} go from wherever it stands; false if it was not held. */
    boolean remove(T element) {
        return held.remove(element);
    }

    /** Lets the first arrival go and returns it, or {@code null} if none is held. */
    T poll() {
        Iterator<T> first = held.iterator();
        if (!first.hasNext()) {
            return null;
        }
        T element = first.next();
        first.remove();
        return element;
    }

    boolean contains(T element) {
        return held.contains(element);
    }

    int size() {
        return held.size();
    }

    boolean isEmpty() {
        return held.isEmpty();
    }

    void clear() {
        held.clear();
    }

    /** A copy, in arrival order. */
    List<T> toList() {
        return new ArrayList<>(held);
    }

    @Override
    public Iterator<T> iterator() {
        return held.iterator();
    }
}
