package masl.translator.generate;

import java.util.HashSet;
import java.util.Set;
import masl.grammar.MASLParser;
import masl.runtime.descriptor.Primitive;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.Sharing;
import masl.translator.analysis.Variable;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * The locals that hold the future of an asynchronous invocation (MASL 9) for one agent type: those
 * assigned or initialised with one. Such a local is a {@code CompletableFuture} field; holding it
 * does not block, reading it awaits the result (contract §3.11); any other value stored in it is an
 * already completed future.
 */
final class FutureVariables {

    private final Set<Variable> variables = new HashSet<>();
    private final AnalyzedProgram program;
    private final TreeQueries queries;

    FutureVariables(AnalyzedProgram program, TreeQueries queries) {
        this.program = program;
        this.queries = queries;
        if (program.root() != null) {
            collect(program.root().tree());
        }
    }

    boolean contains(Variable variable) {
        return variables.contains(variable);
    }

    /** Whether {@code value} is an invocation of an asynchronous primitive: its value is a future. */
    boolean isLaunch(MASLParser.ExpressionContext value) {
        Primitive primitive = queries.invokedPrimitive(value);
        return primitive != null && !primitive.synchronous() && !primitive.returnType().equals("void");
    }

    private void collect(ParseTree tree) {
        if (tree instanceof MASLParser.AssignExprContext assignment && assignment.op.getText().equals("=")
                && assignment.target instanceof MASLParser.PrimaryExprContext && isLaunch(assignment.value)
                && program.symbolOf(assignment.target).orElse(null) instanceof Variable variable) {
            add(variable);
        }
        if (tree instanceof MASLParser.VariableDeclContext declaration && declaration.variableInitializer() != null
                && declaration.variableInitializer().expression() != null
                && isLaunch(declaration.variableInitializer().expression())) {
            for (MASLParser.IdentifierContext name : declaration.identifierList().identifier()) {
                if (program.symbolOf(name).orElse(null) instanceof Variable variable) {
                    add(variable);
                }
            }
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            collect(tree.getChild(i));
        }
    }

    private void add(Variable variable) {
        if (variable.sharing() == Sharing.LOCAL) {
            variables.add(variable);
        }
    }
}
