package masl.lsp;

import java.util.List;
import masl.grammar.MASLLexer;
import org.antlr.v4.runtime.Token;
import org.eclipse.lsp4j.Position;

/**
 * A position in a program, seen through its tokens: the token under it, the ones before it and the block it
 * is in. Positions are compared as code point indexes, as ANTLR's tokens count them.
 */
final class Cursor {

    final ProgramIndex index;
    final TextDocument document;
    /** The cursor's code point index in the text. */
    final int point;
    /** The tokens of the default channel, in order. */
    final List<Token> tokens;
    /** The innermost block around the cursor, or null among the headers. */
    final ProgramIndex.Block scope;

    Cursor(ProgramIndex index, TextDocument document, Position position) {
        this.index = index;
        this.document = document;
        this.point = document.codePointIndex(document.offset(position));
        this.tokens = index.codeTokens();
        this.scope = index.blockAt(point);
    }

    /** The position in {@link #tokens} of the last token that ends before code point {@code at}, or -1. */
    int lastBefore(int at) {
        int low = 0;
        int high = tokens.size() - 1;
        int found = -1;
        while (low <= high) {
            int middle = (low + high) >>> 1;
            if (tokens.get(middle).getStopIndex() < at) {
                found = middle;
                low = middle + 1;
            } else {
                high = middle - 1;
            }
        }
        return found;
    }

    /**
     * The position in {@link #tokens} of the token under the cursor, or -1: the one the cursor is in; at the
     * boundary between two tokens, a name rather than punctuation ({@code work|)} is on {@code work}).
     */
    int tokenAt() {
        int before = lastBefore(point);
        int next = before + 1;
        boolean nextHere = next < tokens.size() && tokens.get(next).getStartIndex() <= point;
        boolean nameEndsHere = before >= 0 && tokens.get(before).getStopIndex() == point - 1
                && Receiver.isName(tokens.get(before));
        if (nextHere && (tokens.get(next).getStartIndex() < point || Receiver.isName(tokens.get(next)) || !nameEndsHere)) {
            return next;
        }
        return nameEndsHere ? before : -1;
    }

    /** Whether the cursor is inside a comment or a string literal, where nothing is completed. */
    boolean inCommentOrString() {
        List<Token> all = index.tokens().getTokens();
        int low = 0;
        int high = all.size() - 1;
        Token last = null;
        while (low <= high) {
            int middle = (low + high) >>> 1;
            if (all.get(middle).getStartIndex() < point) {
                last = all.get(middle);
                low = middle + 1;
            } else {
                high = middle - 1;
            }
        }
        if (last == null) {
            return false;
        }
        int type = last.getType();
        boolean open = type == MASLLexer.LINE_COMMENT || type == MASLLexer.UnterminatedString;
        boolean closed = type == MASLLexer.BLOCK_COMMENT || type == MASLLexer.StringLiteral
                || type == MASLLexer.CharacterLiteral;
        return open && point <= last.getStopIndex() + 1 || closed && point <= last.getStopIndex();
    }

    /** The type of the token at position {@code i} of {@link #tokens}, or -1 outside it. */
    int typeAt(int i) {
        return i >= 0 && i < tokens.size() ? tokens.get(i).getType() : -1;
    }
}
