package masl.translator.generate;

import masl.translator.diagnostics.Diagnostics;
import org.antlr.v4.runtime.ParserRuleContext;

/** Reports the constructs the translator cannot generate, at their position in the program. */
final class Unsupported {

    private final String file;
    private final Diagnostics diagnostics;

    Unsupported(String file, Diagnostics diagnostics) {
        this.file = file;
        this.diagnostics = diagnostics;
    }

    /**
     * Reports {@code construct} at {@code where} and returns a placeholder for the code it would have
     * produced (no Java is compiled once an error is reported).
     */
    String report(ParserRuleContext where, String construct) {
        diagnostics.error(file, where.getStart().getLine(), where.getStart().getCharPositionInLine() + 1,
                construct + " is not supported yet by the translator");
        return "null";
    }

    /** Reports {@code message} at {@code where}: a construct Java cannot hold. */
    void error(ParserRuleContext where, String message) {
        diagnostics.error(file, where.getStart().getLine(), where.getStart().getCharPositionInLine() + 1, message);
    }
}
