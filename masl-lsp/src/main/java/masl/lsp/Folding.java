package masl.lsp;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import masl.grammar.MASLLexer;
import org.antlr.v4.runtime.Token;
import org.eclipse.lsp4j.FoldingRange;
import org.eclipse.lsp4j.FoldingRangeKind;

/**
 * Folding on blocks: every pair of braces spanning lines (entry blocks, reactions, loops, plain blocks) folds,
 * and so does a comment of several lines. Braces are matched on the tokens, so folding follows the program
 * however it is indented; an unmatched brace folds nothing.
 */
final class Folding {

    private Folding() {
    }

    static List<FoldingRange> of(ProgramIndex index) {
        List<FoldingRange> ranges = new ArrayList<>();
        Deque<Token> open = new ArrayDeque<>();
        for (Token token : index.tokens().getTokens()) {
            if (token.getType() == MASLLexer.LBRACE) {
                open.push(token);
            } else if (token.getType() == MASLLexer.RBRACE && !open.isEmpty()) {
                Token start = open.pop();
                // The closing line stays visible, as editors fold a brace block.
                if (token.getLine() - 1 > start.getLine()) {
                    ranges.add(new FoldingRange(start.getLine() - 1, token.getLine() - 2));
                }
            } else if (token.getType() == MASLLexer.BLOCK_COMMENT) {
                int lastLine = token.getLine() + (int) token.getText().chars().filter(c -> c == '\n').count();
                if (lastLine > token.getLine()) {
                    FoldingRange comment = new FoldingRange(token.getLine() - 1, lastLine - 1);
                    comment.setKind(FoldingRangeKind.Comment);
                    ranges.add(comment);
                }
            }
        }
        return ranges;
    }
}
