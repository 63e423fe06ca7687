package masl.cli.timeline;

import com.fasterxml.jackson.core.SerializableString;
import com.fasterxml.jackson.core.io.CharacterEscapes;
import com.fasterxml.jackson.core.io.SerializedString;

/**
 * How JSON is escaped to sit inside an HTML {@code <script>} element: every {@code <} (the one
 * character that can move the HTML tokenizer out of the script's data, through {@code </script},
 * {@code <!--} or {@code <script}) is written {@code \u003C}, and {@code >} and {@code &} likewise, so
 * no string can change how the page is parsed; the line separators U+2028 and U+2029 (line ends to
 * older JavaScript) and every surrogate (a lone one could not be written as UTF-8) are written as
 * {@code \\uXXXX} too. {@code JSON.parse} gives back exactly the strings that were written.
 */
final class ScriptDataEscapes extends CharacterEscapes {

    private static final long serialVersionUID = 1L;

    private final int[] ascii;

    ScriptDataEscapes() {
        ascii = standardAsciiEscapesForJSON();
        ascii['<'] = ESCAPE_STANDARD;
        ascii['>'] = ESCAPE_STANDARD;
        ascii['&'] = ESCAPE_STANDARD;
    }

    @Override
    public int[] getEscapeCodesForAscii() {
        return ascii;
    }

    @Override
    public SerializableString getEscapeSequence(int ch) {
        if (ch == '\u2028' || ch == '\u2029' || Character.isSurrogate((char) ch)) {
            return new SerializedString(String.format("\\u%04x", ch));
        }
        return null;
    }
}
