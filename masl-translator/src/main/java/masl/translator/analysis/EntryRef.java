package masl.translator.analysis;

/**
 * An entry name used as the receiver of an entry member (MASL §6.7): {@code main.count}, {@code turn.lock()}.
 *
 * @param name the name as written ({@code main} for the top-level block whatever its own name)
 * @param block the block it names, or null when no block has that name
 */
public record EntryRef(String name, Block block) implements Symbol {
}
