package masl.translator.analysis;

import java.util.Optional;
import masl.grammar.MaslRuleContext;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * The analysis's findings on parse-tree nodes: the {@link Symbol} each name or member access resolved to,
 * and the {@link MaslType} of each expression. Kept in arrays indexed by the nodes' numbers
 * ({@link MaslRuleContext#index()}, given when the tree was parsed): the analysis records, and the
 * generator asks, several times per node of a program of thousands of lines.
 */
public final class Bindings {

    private final Symbol[] symbols;
    private final MaslType[] types;

    /** Bindings for a tree of {@code nodes} numbered rule nodes. */
    Bindings(int nodes) {
        symbols = new Symbol[nodes];
        types = new MaslType[nodes];
    }

    /**
     * The symbol of a {@code nameExpr}, {@code fieldAccess}, {@code methodCall}, {@code selfInvocation},
     * {@code selfAttribute}, {@code plainCall} or {@code objectCreator} node, of a reaction's or an emit's
     * event, or of a jump's target block; empty when unresolved (an error was reported) or not a name.
     */
    public Optional<Symbol> symbolOf(ParserRuleContext tree) {
        return Optional.ofNullable(symbol(tree));
    }

    /** {@link #symbolOf}, or null: for the many questions of the generator about every node of a subtree. */
    public Symbol symbol(ParserRuleContext tree) {
        int index = ((MaslRuleContext) tree).index();
        return index >= 0 && index < symbols.length ? symbols[index] : null;
    }

    /**
     * The static type of an expression node, or the type a {@code javaType} node of an {@code instanceof}
     * names; {@link MaslType#ERROR} when it has none: an error was reported in it, or it is not a value (a
     * label, an entry or a type name before a {@code .}).
     */
    public MaslType typeOf(ParserRuleContext expression) {
        int index = ((MaslRuleContext) expression).index();
        MaslType type = index >= 0 && index < types.length ? types[index] : null;
        return type == null ? MaslType.ERROR : type;
    }

    void bind(ParserRuleContext tree, Symbol symbol) {
        symbols[slot(tree)] = symbol;
    }

    MaslType type(ParserRuleContext expression, MaslType type) {
        types[slot(expression)] = type;
        return type;
    }

    private static int slot(ParserRuleContext tree) {
        int index = ((MaslRuleContext) tree).index();
        if (index < 0) {
            throw new IllegalArgumentException("a parse-tree node that was not numbered: " + tree.getText());
        }
        return index;
    }
}
