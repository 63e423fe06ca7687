package masl.translator.parse;

import masl.grammar.MASLLexer;
import org.antlr.v4.runtime.DefaultErrorStrategy;
import org.antlr.v4.runtime.Parser;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.misc.IntervalSet;

/**
 * ANTLR's recovery, which goes on after each syntax error, noting whether every repair it made is one
 * a reader makes without a second thought: a {@code ;} left out at the end of a line, a {@code (},
 * {@code )} or {@code ]} left out, a stray token dropped. Then the repaired tree is what the user
 * meant and the analysis may check it; after any other recovery (tokens skipped to resynchronise, a
 * name made up), its findings would be echoes of the syntax error.
 */
final class RecoveryStrategy extends DefaultErrorStrategy {

    private boolean sound = true;

    boolean isSound() {
        return sound;
    }

    @Override
    public void recover(Parser recognizer, RecognitionException e) {
        sound = false;
        super.recover(recognizer, e);
    }

    @Override
    protected void consumeUntil(Parser recognizer, IntervalSet set) {
        if (!set.contains(recognizer.getInputStream().LA(1))) {
            sound = false;
        }
        super.consumeUntil(recognizer, set);
    }

    @Override
    protected Token getMissingSymbol(Parser recognizer) {
        Token missing = super.getMissingSymbol(recognizer);
        int type = missing.getType();
        boolean obvious = type == MASLLexer.RPAREN || type == MASLLexer.LPAREN || type == MASLLexer.RBRACK
                || type == MASLLexer.SEMI && endsLine(recognizer);
        if (!obvious) {
            sound = false;
        }
        return missing;
    }

    /** Whether the token before the parser's position ends its line: a {@code ;} missing there ends a statement. */
    private static boolean endsLine(Parser recognizer) {
        Token next = recognizer.getCurrentToken();
        Token previous = recognizer.getInputStream().LT(-1);
        return previous != null && next.getType() != Token.EOF && previous.getLine() < next.getLine();
    }
}
