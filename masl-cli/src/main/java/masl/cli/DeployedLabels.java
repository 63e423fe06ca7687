package masl.cli;

import masl.grammar.MASLLexer;
import masl.runtime.diagnostic.Diagnostic;
import masl.translator.source.SourceFile;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.Token;

/**
 * Labels ({@code LLabel}, {@code SLabel}) are not available to deployed agents yet: a program that
 * declares one is refused at its first label, before a container is asked to host anything, rather
 * than failing in the middle of the mission when an agent reaches it.
 */
final class DeployedLabels {

    private DeployedLabels() {
    }

    /** The first label declaration of {@code source}, as the error that refuses {@code --deploy}; else null. */
    static Diagnostic refusal(SourceFile source) {
        MASLLexer lexer = new MASLLexer(CharStreams.fromString(source.text(), source.name()));
        lexer.removeErrorListeners();
        for (Token token = lexer.nextToken(); token.getType() != Token.EOF; token = lexer.nextToken()) {
            if (token.getType() == MASLLexer.LLABEL || token.getType() == MASLLexer.SLABEL) {
                return Diagnostic.error(source.name(), token.getLine(), token.getCharPositionInLine() + 1,
                        "labels are not available to deployed agents yet: run this program without --deploy");
            }
        }
        return null;
    }
}
