package masl.translator.analysis;

import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import masl.translator.parse.ProgramParser;
import org.antlr.v4.runtime.ParserRuleContext;

/**
 * What the analysis learnt about a program, for the code generator. Only meaningful when the analysis
 * reported no error; after errors it is as complete as the analysis could make it.
 *
 * @param parsed the parse it was computed from
 * @param types the imported agent types by MASL name, in declaration order
 * @param agents the population, in declaration order (index = proxy id)
 * @param declaredEntries the names declared with {@code Entry …;}
 * @param root the top-level block, or null for a program without one (it only creates its agents)
 * @param bindings the symbol and static type of each name, member access and expression
 */
public record AnalyzedProgram(ProgramParser.Parsed parsed, Map<String, ImportedType> types, List<AgentDecl> agents,
        Set<String> declaredEntries, Block root, Bindings bindings) {

    public AnalyzedProgram {
        types = Collections.unmodifiableMap(types);
        agents = List.copyOf(agents);
        declaredEntries = Collections.unmodifiableSet(declaredEntries);
    }

    /** What a name, member access or call stands for; see {@link Bindings#symbolOf}. */
    public Optional<Symbol> symbolOf(ParserRuleContext tree) {
        return bindings.symbolOf(tree);
    }

    /** What a name, member access or call stands for, or null; see {@link Bindings#symbol}. */
    public Symbol symbol(ParserRuleContext tree) {
        return bindings.symbol(tree);
    }

    /** The static type of an expression; see {@link Bindings#typeOf}. */
    public MaslType typeOf(ParserRuleContext expression) {
        return bindings.typeOf(expression);
    }
}
