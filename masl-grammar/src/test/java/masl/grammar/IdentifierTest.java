package masl.grammar;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.Token;
import org.junit.jupiter.api.Test;

/** Identifiers are Java's letters and digits of any script (MASL §2), ASCII or not. */
class IdentifierTest {

    @Test
    void lettersAndDigitsOfAnyScriptMakeOneName() {
        for (String name : List.of("café", "π2", "x٣", "_a", "$b", "\uD835\uDC65\u0661", "Ωmega_7", "ñandú")) {
            assertEquals(List.of(MASLLexer.Identifier + " " + name), tokens(name), name);
        }
    }

    @Test
    void aDigitOrASymbolIsNoLetter() {
        assertEquals(List.of(MASLLexer.UNEXPECTED_CHAR + " ٣", MASLLexer.Identifier + " x"), tokens("٣x"));
        assertEquals(List.of(MASLLexer.Identifier + " a", MASLLexer.UNEXPECTED_CHAR + " €"), tokens("a€"));
        assertEquals(List.of(MASLLexer.UNEXPECTED_CHAR + " →", MASLLexer.Identifier + " b"), tokens("→b"));
    }

    private static List<String> tokens(String text) {
        return new MASLLexer(CharStreams.fromString(text)).getAllTokens().stream()
                .filter(token -> token.getChannel() == Token.DEFAULT_CHANNEL)
                .map(token -> token.getType() + " " + token.getText())
                .toList();
    }
}
