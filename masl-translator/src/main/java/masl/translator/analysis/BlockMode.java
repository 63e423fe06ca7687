package masl.translator.analysis;

/** The rhythm of a block's members (MASL §6.2). */
public enum BlockMode {
    SCALAR, SYNCHRONOUS, ASYNCHRONOUS;

    /** The keyword, for messages. */
    public String keyword() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
