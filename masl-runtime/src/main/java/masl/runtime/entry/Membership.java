package masl.runtime.entry;

/**
 * One agent's membership of one block: an element of the agent's chain of blocks, innermost last.
 * Changed only under the {@link EntryCoordinator}'s lock.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Membership {

    /** Where the member stands (MASL §1). */
    public enum Status { WAITING_IN, ACTIVE, WAITING_OUT }

    public final Entry entry;
    /** The wave the agent belongs to; {@code null} while it is held by the entry barrier. */
    public Wave wave;
    public Status status;

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
