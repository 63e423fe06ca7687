package masl.translator.parse;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.List;
import masl.grammar.MASLLexer;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.source.SourceFile;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.Token;

/**
 * How deeply a program nests, read from its tokens before it is parsed. ANTLR's parser, the analysis,
 * the generator and javac all recurse into nested constructs; they run on a thread with a deep stack
 * ({@code masl.translator.DeepStack}), deep enough for {@value #DEEPEST} levels of any construct.
 *
 * <p>The level of a token is the number of brackets open around it plus, within each of them, the
 * operators and keywords since its expression or statement began: {@code a + b + c}, {@code - - x},
 * {@code if (x) if (y)} and {@code else if ... else if} nest in the parse tree as brackets do. A
 * program whose level passes {@value #DEEPEST} is refused at the first token past it, before
 * parsing.
 */
public final class Nesting {

    /** The deepest level masl translates. */
    public static final int DEEPEST = 10_000;

    private Nesting() {
    }

    /** Reports the first token nested deeper than {@value #DEEPEST}, if any; returns whether it did. */
    static boolean reportTooDeep(String file, List<Token> tokens, Diagnostics diagnostics) {
        Levels levels = new Levels();
        for (Token token : tokens) {
            if (levels.next(token) > DEEPEST) {
                report(file, token, diagnostics);
                return true;
            }
        }
        return false;
    }

    /**
     * Reports a program that exhausted the deep stack all the same (a construct this measure does not
     * see), at its most deeply nested token.
     */
    public static void reportTooDeep(SourceFile source, Diagnostics diagnostics) {
        MASLLexer lexer = new MASLLexer(CharStreams.fromString(source.text(), source.name()));
        lexer.removeErrorListeners();
        CommonTokenStream stream = new CommonTokenStream(lexer);
        stream.fill();
        Levels levels = new Levels();
        Token deepest = null;
        int most = -1;
        for (Token token : stream.getTokens()) {
            int level = levels.next(token);
            if (level > most) {
                most = level;
                deepest = token;
            }
        }
        report(source.name(), deepest, diagnostics);
    }

    private static void report(String file, Token token, Diagnostics diagnostics) {
        diagnostics.error(file, token.getLine(), token.getCharPositionInLine() + 1, String.format(
                "the program nests too deeply here: masl translates at most %,d levels of brackets,"
                        + " operators and statements within statements", DEEPEST));
    }

    /** The level of each token in turn. */
    private static final class Levels {
        /** The chain of each enclosing bracket, where it was opened. */
        private final Deque<Integer> outer = new ArrayDeque<>();
        private int outerSum;
        private int chain;
        private Token previous;

        int next(Token token) {
            if (token.getChannel() != Token.DEFAULT_CHANNEL) {
                return outer.size() + outerSum + chain;
            }
            if (endsStatement(previous) && token.getType() != MASLLexer.ELSE) {
                chain = 0;
            }
            int type = token.getType();
            if (type == MASLLexer.LPAREN || type == MASLLexer.LBRACE || type == MASLLexer.LBRACK) {
                outer.push(chain);
                outerSum += chain;
                chain = 0;
            } else if (type == MASLLexer.RPAREN || type == MASLLexer.RBRACE || type == MASLLexer.RBRACK) {
                if (!outer.isEmpty()) {
                    chain = outer.pop();
                    outerSum -= chain;
                }
            } else if (!isOperand(type)) {
                chain++;
            }
            previous = token;
            return outer.size() + outerSum + chain;
        }

        private static boolean endsStatement(Token token) {
            return token != null && (token.getType() == MASLLexer.SEMI || token.getType() == MASLLexer.RBRACE
                    || token.getType() == MASLLexer.COMMA);
        }

        private static boolean isOperand(int type) {
            return type == MASLLexer.Identifier || type == MASLLexer.IntegerLiteral
                    || type == MASLLexer.FloatingPointLiteral || type == MASLLexer.StringLiteral
                    || type == MASLLexer.CharacterLiteral || type == MASLLexer.SEMI || type == MASLLexer.COMMA
                    || type == Token.EOF;
        }
    }
}
