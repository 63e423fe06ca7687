package masl.translator.generate;

import masl.grammar.MASLParser;
import masl.translator.analysis.AnalyzedProgram;
import masl.translator.analysis.Member;
import masl.translator.analysis.Sharing;
import masl.translator.analysis.Variable;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * Decides, per loop, whether it is a busy-wait (generated-code contract §3.8): its condition and
 * the conditions in its body read only what the runtime sees change (shared variables, entry
 * members, label members, accept states, literals, locals), and its body assigns no local. Such a loop parks when nothing it can
 * observe changed; any other loop only yields.
 */
final class LoopClassifier {

    private final AnalyzedProgram program;

    LoopClassifier(AnalyzedProgram program) {
        this.program = program;
    }

    /**
     * @param condition the loop's condition, or null for {@code do … loop}
     * @param body the loop's body
     */
    boolean isBusyWait(MASLParser.ExpressionContext condition, ParseTree body) {
        return (condition == null || readsOnlyObservable(condition)) && conditionsObservable(body)
                && !assignsLocal(body);
    }

    private boolean conditionsObservable(ParseTree tree) {
        if (tree instanceof MASLParser.IfStmtContext ifStmt && !readsOnlyObservable(ifStmt.expression())) {
            return false;
        }
        if (tree instanceof MASLParser.WhileStmtContext loop && !readsOnlyObservable(loop.expression())) {
            return false;
        }
        if (tree instanceof MASLParser.ForStmtContext) {
            return false;
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (!conditionsObservable(tree.getChild(i))) {
                return false;
            }
        }
        return true;
    }

    private boolean readsOnlyObservable(ParseTree tree) {
        if (tree instanceof MASLParser.NewExprContext || tree instanceof MASLParser.AssignExprContext
                || tree instanceof MASLParser.PostfixExprContext) {
            return false;
        }
        if (tree instanceof ParserRuleContext node && program.symbolOf(node).orElse(null) instanceof Member member
                && !isObservable(member)) {
            return false;
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (!readsOnlyObservable(tree.getChild(i))) {
                return false;
            }
        }
        return true;
    }

    private static boolean isObservable(Member member) {
        return switch (member.kind()) {
            case ENTRY_MEMBER -> true;
            // A label's completions and free() advance the change epoch (contract §8.3).
            case LABEL_MEMBER -> !member.name().equals("free");
            // The agent's id never changes.
            case PRIMITIVE -> member.name().equals("getProxyID");
            case JAVA_FIELD -> member.name().equals("length") || member.name().equals("class");
            default -> false;
        };
    }

    private boolean assignsLocal(ParseTree tree) {
        ParserRuleContext target = null;
        if (tree instanceof MASLParser.AssignExprContext assignment) {
            target = assignment.target;
        } else if (tree instanceof MASLParser.PostfixExprContext postfix) {
            target = postfix.expression();
        } else if (tree instanceof MASLParser.PrefixExprContext prefix
                && (prefix.op.getText().equals("++") || prefix.op.getText().equals("--"))) {
            target = prefix.expression();
        }
        if (target != null && program.symbolOf(target).orElse(null) instanceof Variable variable
                && variable.sharing() == Sharing.LOCAL) {
            return true;
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (assignsLocal(tree.getChild(i))) {
                return true;
            }
        }
        return false;
    }
}
