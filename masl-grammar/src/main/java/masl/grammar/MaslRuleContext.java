package masl.grammar;

import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.tree.ErrorNode;
import org.antlr.v4.runtime.tree.ParseTreeListener;
import org.antlr.v4.runtime.tree.TerminalNode;

/**
 * The base class of every rule node of the MASL parse tree (the grammar's {@code contextSuperClass}):
 * a rule node with a number, dense in its tree, so that what a later pass learns about nodes can be
 * kept in arrays indexed by it instead of maps keyed by the nodes. A {@link Numbering} listener
 * numbers the nodes while the parser builds them; a node not numbered has index -1.
 */
public class MaslRuleContext extends ParserRuleContext {

    private int index = -1;

    public MaslRuleContext() {
    }

    public MaslRuleContext(ParserRuleContext parent, int invokingStateNumber) {
        super(parent, invokingStateNumber);
    }

    /** This node's number in its tree, from 0; -1 if the tree was not numbered. */
    public final int index() {
        return index;
    }

    /**
     * A parse listener ({@link org.antlr.v4.runtime.Parser#addParseListener}) that numbers the rule nodes
     * 0, 1, 2, … as the parser completes them: in the tree they are numbered while they are still in the
     * processor's cache, and a node the parser replaced (by the node of a labelled alternative) gets none.
     */
    public static final class Numbering implements ParseTreeListener {
        private int count;

        /** How many nodes were numbered: the indexes go from 0 to {@code count() - 1}. */
        public int count() {
            return count;
        }

        @Override
        public void exitEveryRule(ParserRuleContext node) {
            ((MaslRuleContext) node).index = count++;
        }

        @Override
        public void enterEveryRule(ParserRuleContext node) {
        }

        @Override
        public void visitTerminal(TerminalNode node) {
        }

        @Override
        public void visitErrorNode(ErrorNode node) {
        }
    }
}
