package masl.translator.generate;

import java.util.ArrayList;
import java.util.List;
import masl.grammar.MASLParser;
import masl.grammar.MASLParser.ExpressionContext;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.MaslType;
import masl.translator.analysis.Sharing;
import masl.translator.analysis.Variable;

/**
 * Stores into an element of an array a shared variable holds ({@code a[i] = e}, {@code a[i][j] += e},
 * {@code a[i]++}): Java's store on the array {@code get()} gives, wrapped in the variable's {@code
 * stored(value, i, j)}, which says which element the program stored. In-process the array is the
 * variable's own, and {@code stored} does nothing more; a deployed agent's copy of the variable has
 * the mission, which owns the array, store the element in its own (docs/decisions.md, "Elements of
 * shared arrays"). An index is evaluated once: one that is not a literal or a local is kept in a
 * temporary as the store evaluates it, which the path then names.
 */
final class SharedElementWriter {

    private final AnalyzedProgram program;
    private final StaticStructure structure;
    private final ExpressionWriter expressions;
    private final AssignmentWriter assignments;

    SharedElementWriter(AnalyzedProgram program, StaticStructure structure, ExpressionWriter expressions,
            AssignmentWriter assignments) {
        this.program = program;
        this.structure = structure;
        this.expressions = expressions;
        this.assignments = assignments;
    }

    /** The shared variable whose array {@code target} is an element of, or null if it is not one. */
    Variable sharedArray(ExpressionContext target) {
        if (!(target instanceof MASLParser.ArrayAccessContext)) {
            return null;
        }
        return program.symbolOf(array(target)).orElse(null) instanceof Variable variable && isShared(variable)
                ? variable : null;
    }

    /** {@code target op value}: {@code value} already in Java, converted as the operator needs. */
    String assignment(Variable array, ExpressionContext target, String operator, String value, boolean isStatement) {
        Element element = element(target, expressions.expr(array(target)));
        return typed(target, isStatement, shared(array) + ".stored(" + element.access() + " " + operator + " " + value
                + ", " + element.path() + ")");
    }

    /** {@code ++target}, {@code target--}, …: the value an expression needs, the old one for a postfix. */
    String increment(Variable array, ExpressionContext target, String operator, boolean prefix, boolean isStatement) {
        if (prefix || isStatement) {
            Element element = element(target, expressions.expr(array(target)));
            return typed(target, isStatement, shared(array) + ".stored(" + operator + element.access() + ", "
                    + element.path() + ")");
        }
        // The element before is the expression's value; the one after is read from the same array.
        String copy = assignments.temporary(JavaTypes.name(array.type()));
        Element element = element(target, "(" + copy + " = " + expressions.expr(array(target)) + ")");
        return typed(target, false, shared(array) + ".postfixStored(" + element.access() + operator + ", "
                + copy + "[" + String.join("][", element.indices()) + "], " + element.path() + ")");
    }

    /** The array expression of element {@code target}: {@code a} of {@code a[i][j]}. */
    private static ExpressionContext array(ExpressionContext target) {
        ExpressionContext array = target;
        while (array instanceof MASLParser.ArrayAccessContext access) {
            array = access.expression(0);
        }
        return array;
    }

    private boolean isShared(Variable variable) {
        return variable.sharing() == Sharing.SHARED && !expressions.holdsFuture(variable);
    }

    private String shared(Variable array) {
        return "ctx.shared(" + structure.shared(array) + ")";
    }

    /** In an expression, the element's own type rather than its box, as Java's assignment has. */
    private String typed(ExpressionContext target, boolean isStatement, String java) {
        MaslType type = program.typeOf(target);
        return isStatement || !JavaTypes.isPrimitive(type) ? java : "((" + JavaTypes.name(type) + ") " + java + ")";
    }

    /** The element's access on {@code array} (Java), its indices each evaluated once, and its path. */
    private Element element(ExpressionContext target, String array) {
        List<ExpressionContext> indices = new ArrayList<>();
        for (ExpressionContext at = target; at instanceof MASLParser.ArrayAccessContext access; at = access.expression(0)) {
            indices.add(0, access.index);
        }
        StringBuilder access = new StringBuilder(array);
        List<String> path = new ArrayList<>();
        for (ExpressionContext index : indices) {
            String java = expressions.expr(index);
            if (isLiteralOrLocal(index)) {
                access.append('[').append(java).append(']');
                path.add(java);
            } else {
                String temporary = assignments.temporary("int");
                access.append('[').append(temporary).append(" = ").append(java).append(']');
                path.add(temporary);
            }
        }
        return new Element(access.toString(), path);
    }

    private boolean isLiteralOrLocal(ExpressionContext index) {
        if (!(index instanceof MASLParser.PrimaryExprContext primary)) {
            return false;
        }
        if (primary.primary() instanceof MASLParser.LiteralExprContext) {
            return true;
        }
        return primary.primary() instanceof MASLParser.NameExprContext
                && program.symbolOf(index).orElse(null) instanceof Variable variable
                && variable.sharing() == Sharing.LOCAL && !expressions.holdsFuture(variable);
    }

    /** An element's access, its indices' evaluation included, and the names of its indices once evaluated. */
    private record Element(String access, List<String> indices) {
        String path() {
            return String.join(", ", indices);
        }
    }
}
