package masl.translator.analysis;

import masl.translator.diagnostics.Diagnostics;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;

/** Reports semantic errors of one program file at the position of the token a user should look at. */
final class Errors {

    private final String file;
    private final Diagnostics diagnostics;

    Errors(String file, Diagnostics diagnostics) {
        this.file = file;
        this.diagnostics = diagnostics;
    }

    void at(Token token, String message) {
        diagnostics.error(file, token.getLine(), token.getCharPositionInLine() + 1, message);
    }

    void at(ParserRuleContext tree, String message) {
        at(tree.getStart(), message);
    }

    Diagnostics diagnostics() {
        return diagnostics;
    }
}
