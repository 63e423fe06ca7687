package masl.runtime.entry;

/** The policy of a block's entry barrier (MASL §6.3, §6.7 {@code getLockPolicy()}). */
public enum LockPolicy {
    /** Asynchronous and scalar blocks have no entry barrier. */
    UNAVAILABLE("unavailable"),
    /** The block never had a wave: waiting agents go in once the e-sequence has been reached by all. */
    FREE("free"),
    /** Only {@code release()} and {@code release(n)} let waiting agents in. */
    LOCKED("locked");

    private final String maslName;

    LockPolicy(String maslName) {
        this.maslName = maslName;
    }

    /** The name MASL programs compare with: {@code "unavailable"}, {@code "free"}, {@code "locked"}. */
    public String maslName() {
        return maslName;
    }
}
