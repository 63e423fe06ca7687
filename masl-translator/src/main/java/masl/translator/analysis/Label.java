package masl.translator.analysis;

/**
 * A label collecting asynchronous invocations (MASL §10): {@code LLabel} (one per member, {@link Sharing#LOCAL})
 * or {@code SLabel} (one per wave, {@link Sharing#SHARED}).
 */
public record Label(String name, Sharing sharing, Block block) implements Symbol {
}
