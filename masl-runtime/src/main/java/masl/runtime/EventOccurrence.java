package masl.runtime;

/** One perceived occurrence of an event (MASL §8), with its message ({@code ""} if none). */
public record EventOccurrence(String event, String message) {
}
