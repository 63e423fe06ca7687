package masl.jade;

/**
 * An exception class whose static initialiser leaves a mark ({@link #MARK}, a system property): a
 * forged {@code FAILURE} naming it must never get it initialised.
 */
public final class Detonator extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public static final String MARK = "masl.jade.test.detonated";

    static {
        System.setProperty(MARK, "yes");
    }

    public Detonator(String message) {
        super(message);
    }
}
