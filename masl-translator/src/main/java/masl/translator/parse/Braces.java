package masl.translator.parse;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import masl.grammar.MASLLexer;
import org.antlr.v4.runtime.Token;

/**
 * A program with more {@code {} than {@code }} (or fewer) is read as its indentation shows it: a
 * block ends where a line starts at or left of the line that opened it, so a missing {@code }} is
 * reported where it belongs (after the block's last line, not at the end of the file) and the rest of
 * the file parses as the user laid it out; an extra {@code }} is one after which its block visibly
 * goes on. Only as many braces as are missing, or extra, are placed or dropped. A guess: the analysis
 * does not run on what it repaired.
 */
final class Braces {

    private record Open(Token brace, int indent) { }

    private final TokenRepairs repairs;

    Braces(TokenRepairs repairs) {
        this.repairs = repairs;
    }

    void balance() {
        List<Token> significant = repairs.significant();
        int balance = 0;
        for (Token token : significant) {
            balance += token.getType() == MASLLexer.LBRACE ? 1 : token.getType() == MASLLexer.RBRACE ? -1 : 0;
        }
        if (balance > 0) {
            closeUnclosed(significant, balance);
        } else if (balance < 0) {
            dropExtra(significant, -balance);
        }
    }

    private void closeUnclosed(List<Token> significant, int missing) {
        Deque<Open> open = new ArrayDeque<>();
        for (int i = 0; i < significant.size() && missing > 0; i++) {
            Token token = significant.get(i);
            if (i > 0 && startsLine(significant, i)) {
                int indent = token.getCharPositionInLine();
                while (missing > 0 && !open.isEmpty() && (indent < open.peek().indent()
                        || indent == open.peek().indent() && token.getType() != MASLLexer.RBRACE)) {
                    Token last = significant.get(i - 1);
                    repairs.error(last.getLine(), endColumn(last), "expected '}' to close the '{' of line "
                            + open.pop().brace().getLine());
                    repairs.insertAfter(last, MASLLexer.RBRACE, "}");
                    repairs.unsound();
                    missing--;
                }
            }
            if (token.getType() == MASLLexer.LBRACE) {
                open.push(new Open(token, indentOfLine(significant, i)));
            } else if (token.getType() == MASLLexer.RBRACE && !open.isEmpty()) {
                open.pop();
            }
        }
    }

    private void dropExtra(List<Token> significant, int extra) {
        Deque<Open> open = new ArrayDeque<>();
        for (int i = 0; i < significant.size() && extra > 0; i++) {
            Token token = significant.get(i);
            if (token.getType() == MASLLexer.LBRACE) {
                open.push(new Open(token, indentOfLine(significant, i)));
            } else if (token.getType() == MASLLexer.RBRACE) {
                boolean goesOn = !open.isEmpty() && startsLine(significant, i) && i + 1 < significant.size()
                        && startsLine(significant, i + 1)
                        && token.getCharPositionInLine() > open.peek().indent()
                        && significant.get(i + 1).getCharPositionInLine() > open.peek().indent();
                if (open.isEmpty() || goesOn) {
                    repairs.error(token.getLine(), token.getCharPositionInLine() + 1,
                            "unexpected '}': no block ends here");
                    TokenRepairs.hide(token);
                    repairs.unsound();
                    extra--;
                } else {
                    open.pop();
                }
            }
        }
    }

    private static boolean startsLine(List<Token> significant, int i) {
        return i == 0 || significant.get(i - 1).getLine() < significant.get(i).getLine();
    }

    /** The column of the first token of the line that holds token {@code i}. */
    private static int indentOfLine(List<Token> significant, int i) {
        int first = i;
        while (first > 0 && significant.get(first - 1).getLine() == significant.get(i).getLine()) {
            first--;
        }
        return significant.get(first).getCharPositionInLine();
    }

    /** The column just after a token, where a missing '}' belongs. */
    private static int endColumn(Token token) {
        return token.getCharPositionInLine() + token.getText().length() + 1;
    }
}
