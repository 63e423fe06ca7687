package masl.translator.analysis;

import masl.grammar.MASLParser;

/**
 * A {@code react} of a block (MASL §8). A block's reactions are kept in source order, which is their priority.
 *
 * @param event the event reacted to, or null for {@code react(default)}
 * @param block the block the reaction belongs to
 * @param tree its parse tree, for the statements
 */
public record Reaction(EventDecl event, Block block, MASLParser.ReactionContext tree) {

    public boolean isDefault() {
        return event == null;
    }
}
