package masl.agents;

/**
 * Thrown by a primitive of a soft robot whose battery is empty: the motion did not happen. In a
 * MASL program it becomes an {@code uncaught_exception} whose message is this class's name.
 */
public final class BatteryEmptyException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    public BatteryEmptyException() {
        super("the battery is empty");
    }
}
