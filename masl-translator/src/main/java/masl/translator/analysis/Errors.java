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

    /**
     * A member of a value that has none, the {@code .} starting a line ({@code .log("a")} then
     * {@code .logln("b");} on the next line): the {@code ;} ending the line before was forgotten, so
     * the value is a statement of its own. Reports that, where javac would, and returns true;
     * false if the {@code .} follows its value on one line.
     */
    boolean missingSemicolonBefore(Token dot, ParserRuleContext value) {
        Token end = value.getStop();
        if (end == null || end.getLine() >= dot.getLine()) {
            return false;
        }
        diagnostics.error(file, end.getLine(), end.getCharPositionInLine() + end.getText().length() + 1, "expected ';'");
        return true;
    }

    Diagnostics diagnostics() {
        return diagnostics;
    }
}
