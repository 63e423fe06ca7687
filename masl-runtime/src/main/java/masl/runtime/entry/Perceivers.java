package masl.runtime.entry;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.function.IntFunction;

/**
 * The members of one block as the receivers of its shared events (§8): changed in O(1) amortised
 * under the {@link EntryCoordinator}'s lock, read without any lock by emitters.
 *
 * <p>Members are slots appended in arrival order; leaving stamps the slot with the version of the
 * change instead of copying the array. A reader takes the published {@link Snapshot} (slot array,
 * size and version, one volatile read) and keeps the slots not stamped at or before that version:
 * a stamp written after the snapshot's version is either not seen or seen as later, so both read
 * as "still a member", and the reader sees exactly the members as of the snapshot's change. When
 * half the slots are stamped, the live ones are copied to a new array (amortised O(1) per leave);
 * readers holding the old array still read it correctly, since slots are shared, never reused.
 */
final class Perceivers<T> {

    private static final class Slot<T> {
        final T member;
        /** The version of the change that removed the member; {@code Long.MAX_VALUE} while it is one. */
        volatile long leftAt = Long.MAX_VALUE;

        Slot(T member) {
            this.member = member;
        }
    }

    private record Snapshot<T>(Slot<T>[] slots, int size, long version) { }

    // Guarded by the coordinator's lock.
    private final Map<T, Slot<T>> live = new HashMap<>();
    private Slot<T>[] slots = newSlots(4);
    private int size;
    private long version;
    private volatile Snapshot<T> published = new Snapshot<>(slots, 0, 0);

    /** Adds a member; called under the coordinator's lock. */
    void add(T member) {
        if (live.containsKey(member)) {
            return;
        }
        if (size == slots.length) {
            slots = Arrays.copyOf(slots, size * 2);
        }
        Slot<T> slot = new Slot<>(member);
        slots[size++] = slot;
        live.put(member, slot);
        publish(++version);
    }

    /** Removes a member; called under the coordinator's lock. */
    void remove(T member) {
        Slot<T> slot = live.remove(member);
        if (slot == null) {
            return;
        }
        slot.leftAt = ++version;
        if (live.size() * 2 < size) {
            compact();
        }
        publish(version);
    }

    /** The members as of the last change, in arrival order; lock-free. */
    T[] snapshot(IntFunction<T[]> newArray) {
        Snapshot<T> snapshot = published;
        T[] members = newArray.apply(snapshot.size());
        int count = 0;
        for (int i = 0; i < snapshot.size(); i++) {
            Slot<T> slot = snapshot.slots()[i];
            if (slot.leftAt > snapshot.version()) {
                members[count++] = slot.member;
            }
        }
        return count == members.length ? members : Arrays.copyOf(members, count);
    }

    private void compact() {
        Slot<T>[] kept = newSlots(Math.max(4, live.size() * 2));
        int count = 0;
        for (int i = 0; i < size; i++) {
            if (slots[i].leftAt == Long.MAX_VALUE) {
                kept[count++] = slots[i];
            }
        }
        slots = kept;
        size = count;
    }

    private void publish(long atVersion) {
        published = new Snapshot<>(slots, size, atVersion);
    }

    @SuppressWarnings("unchecked")
    private static <T> Slot<T>[] newSlots(int length) {
        return (Slot<T>[]) new Slot<?>[length];
    }
}
