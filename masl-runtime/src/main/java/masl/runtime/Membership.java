package masl.runtime;

/**
 * One agent's membership of one block: an element of the agent's chain of blocks, innermost last.
 * Changed only under the {@link EntryCoordinator}'s lock.
 */
final class Membership {

    /** Where the member stands (MASL §1). */
    enum Status { WAITING_IN, ACTIVE, WAITING_OUT }

    final Entry entry;
    /** The wave the agent belongs to; {@code null} while it is held by the entry barrier. */
    Wave wave;
    Status status;

    Membership(Entry entry, Wave wave, Status status) {
        this.entry = entry;
        this.wave = wave;
        this.status = status;
    }

    @Override
    public String toString() {
        return entry.name() + (status == Status.ACTIVE ? "" : "(" + status.name().toLowerCase().replace('_', '-') + ")");
    }
}
