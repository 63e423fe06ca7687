package masl.translator.analysis;

import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * The analysis's findings on parse-tree nodes: the {@link Symbol} each name or member access resolved to,
 * and the {@link MaslType} of each expression. Keys are the parse-tree nodes themselves (identity).
 */
public final class Bindings {

    private final Map<ParserRuleContext, Symbol> symbols = new HashMap<>();
    private final Map<ParserRuleContext, MaslType> types = new HashMap<>();

    /**
     * The symbol of a {@code nameExpr}, {@code fieldAccess}, {@code methodCall}, {@code selfInvocation},
     * {@code selfAttribute}, {@code plainCall} or {@code objectCreator} node, of a reaction's or an emit's
     * event, or of a jump's target block; empty when unresolved (an error was reported) or not a name.
     */
    public Optional<Symbol> symbolOf(ParserRuleContext tree) {
        return Optional.ofNullable(symbols.get(tree));
    }

    /**
     * The static type of an expression node, or the type a {@code javaType} node of an {@code instanceof}
     * names; {@link MaslType#ERROR} when it has none: an error was reported in it, or it is not a value (a
     * label, an entry or a type name before a {@code .}).
     */
    public MaslType typeOf(ParserRuleContext expression) {
        return types.getOrDefault(expression, MaslType.ERROR);
    }

    void bind(ParserRuleContext tree, Symbol symbol) {
        symbols.put(tree, symbol);
    }

    MaslType type(ParserRuleContext expression, MaslType type) {
        types.put(expression, type);
        return type;
    }
}
