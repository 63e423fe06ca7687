package masl.translator.analysis;

import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.antlr.v4.runtime.Token;

/**
 * Entry names used as receivers of entry members (MASL §6.7): {@code main} for the top-level block, and
 * the names declared with {@code Entry name;}. Entry names are unique in a program, so one map suffices.
 */
final class EntryNames {

    static final String MAIN = "main";

    private final Block root;
    private final Map<String, Block> blocksByName;
    private final Set<String> declared;
    private final Errors errors;

    EntryNames(Block root, Map<String, Block> blocksByName, Set<String> declared, Errors errors) {
        this.root = root;
        this.blocksByName = blocksByName;
        this.declared = declared;
        this.errors = errors;
    }

    /** The names of the blocks, for hints. */
    Set<String> names() {
        return blocksByName.keySet();
    }

    /**
     * The entry a name denotes as a receiver, or empty when no block has that name. A block that is not
     * declared with {@code Entry} is reported, and still returned so that its members raise no more errors.
     */
    Optional<EntryRef> receiver(Token name) {
        String text = name.getText();
        if (text.equals(MAIN)) {
            return Optional.of(new EntryRef(MAIN, root));
        }
        Block block = blocksByName.get(text);
        if (declared.contains(text)) {
            return Optional.of(new EntryRef(text, block));
        }
        if (block != null) {
            errors.at(name, "entry " + text + " is not declared: add 'Entry " + text + ";' to use its members");
            return Optional.of(new EntryRef(text, block));
        }
        return Optional.empty();
    }

    /** The block a jump names: an enclosing block of {@code from} (itself included), or {@code main}. */
    Optional<Block> enclosing(String name, Block from) {
        if (name.equals(MAIN)) {
            return Optional.of(root);
        }
        for (Block block = from; block != null; block = block.parent()) {
            if (block.name().equals(name)) {
                return Optional.of(block);
            }
        }
        return Optional.empty();
    }
}
