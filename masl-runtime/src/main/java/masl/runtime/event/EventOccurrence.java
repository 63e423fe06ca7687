package masl.runtime.event;

import java.util.Objects;
import masl.runtime.Event;

/**
 * One emission of an event (MASL §8) as its receivers perceive it: immutable, shared by all of them.
 *
 * @param event the event emitted
 * @param message the message of {@code emitWithMessage}, {@code ""} for a plain {@code emit}
 * @param emitter the proxy id of the emitting agent
 */
public record EventOccurrence(Event event, String message, int emitter) {

    public EventOccurrence {
        Objects.requireNonNull(event, "event");
        Objects.requireNonNull(message, "message");
    }
}
