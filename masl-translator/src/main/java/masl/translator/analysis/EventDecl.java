package masl.translator.analysis;

import java.util.List;

/**
 * An event (MASL §8): declared in a block, or one of the system events, which are local and
 * implicitly declared everywhere.
 *
 * @param block the declaring block, null for a system event
 */
public record EventDecl(String name, Sharing sharing, Block block) implements Symbol {

    /** {@code timeout}, {@code uncaught_exception} and {@code forbidden_access}. */
    public static final List<EventDecl> SYSTEM_EVENTS = List.of(
            new EventDecl("timeout", Sharing.LOCAL, null),
            new EventDecl("uncaught_exception", Sharing.LOCAL, null),
            new EventDecl("forbidden_access", Sharing.LOCAL, null));

    public boolean isSystemEvent() {
        return block == null;
    }
}
