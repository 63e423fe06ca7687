package masl.translator.analysis;

import java.util.Locale;

/** The rhythm of a block's members (MASL §6.2). */
public enum BlockMode {
    SCALAR, SYNCHRONOUS, ASYNCHRONOUS;

    /** The keyword, for messages. */
    public String keyword() {
        return name().toLowerCase(Locale.ROOT);
    }
}
