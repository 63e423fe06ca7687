package masl.translator.parse;

/**
 * The values of MASL's string and character literals, decoded as javac decodes Java's (JLS 3.3,
 * 3.10.4 to 3.10.7): escape sequences {@code \b \t \n \f \r \" \' \\}, octal escapes ({@code \0} to
 * {@code \377}, as many digits as Java takes), and Unicode escapes {@code \}{@code uXXXX} (any number
 * of {@code u}) standing for their character. javac replaces a Unicode escape before it reads the
 * literal at all, so one standing for a line break, for the literal's own quote or for a backslash
 * would end the literal, break the line or start an escape there: the program would not mean what
 * it shows. Those are errors, at the escape; every other literal has the value Java gives it, and the
 * generated Java is written from that value, never from the source text.
 */
public final class Literals {

    /** Why a literal cannot be read as it shows, at {@code offset} (a UTF-16 index into its source text). */
    public static final class Problem extends Exception {
        private static final long serialVersionUID = 1L;

        private final int offset;

        Problem(int offset, String message) {
            super(message, null, false, false);
            this.offset = offset;
        }

        public int offset() {
            return offset;
        }
    }

    private Literals() {
    }

    /** The value of a string literal, {@code text} its source with the quotes. */
    public static String string(String text) throws Problem {
        return body(text, '"', "string");
    }

    /** The value of a character literal, {@code text} its source with the quotes. */
    public static char character(String text) throws Problem {
        String value = body(text, '\'', "character literal");
        if (value.length() != 1) {
            throw new Problem(1, "a character literal holds one UTF-16 char; " + text + " holds " + value.length()
                    + ": write it as a String");
        }
        return value.charAt(0);
    }

    private static String body(String text, char quote, String what) throws Problem {
        StringBuilder value = new StringBuilder(text.length());
        int end = text.length() - 1;
        int i = 1;
        while (i < end) {
            char c = text.charAt(i);
            if (c != '\\') {
                value.append(c);
                i++;
            } else if (i + 1 < end && text.charAt(i + 1) == 'u') {
                i = unicodeEscape(text, i, end, quote, what, value);
            } else {
                i = escapeSequence(text, i, end, value);
            }
        }
        return value.toString();
    }

    /** Decodes the Unicode escape at {@code start} into {@code value}; returns the index after it. */
    private static int unicodeEscape(String text, int start, int end, char quote, String what, StringBuilder value)
            throws Problem {
        int digits = start + 1;
        while (digits < end && text.charAt(digits) == 'u') {
            digits++;
        }
        if (digits + 4 > end || !isHex(text.substring(digits, digits + 4))) {
            throw new Problem(start, "illegal Unicode escape: \\u must be followed by four hexadecimal digits");
        }
        char decoded = (char) Integer.parseInt(text.substring(digits, digits + 4), 16);
        String escape = text.substring(start, digits + 4);
        if (decoded == '\n' || decoded == '\r') {
            throw new Problem(start, escape + " is a line break, which ends the line in Java before the " + what
                    + " is read: write " + (decoded == '\n' ? "\\n" : "\\r"));
        }
        if (decoded == quote) {
            throw new Problem(start, escape + " is " + quote + ", which Java reads as the end of the " + what
                    + ": write \\" + quote);
        }
        if (decoded == '\\') {
            throw new Problem(start, escape + " is a backslash, which Java reads as the start of an escape"
                    + " sequence: write \\\\");
        }
        value.append(decoded);
        return digits + 4;
    }

    /** Decodes the escape sequence at {@code start} (not a Unicode escape) into {@code value}; returns the index after it. */
    private static int escapeSequence(String text, int start, int end, StringBuilder value) throws Problem {
        if (start + 1 >= end) {
            throw new Problem(start, "a backslash must start an escape sequence");
        }
        char next = text.charAt(start + 1);
        char simple = switch (next) {
            case 'b' -> '\b';
            case 't' -> '\t';
            case 'n' -> '\n';
            case 'f' -> '\f';
            case 'r' -> '\r';
            case '"', '\'', '\\' -> next;
            default -> 0;
        };
        if (simple != 0) {
            value.append(simple);
            return start + 2;
        }
        if (next < '0' || next > '7') {
            throw new Problem(start, "illegal escape sequence \\" + next);
        }
        // Java takes three octal digits only when the first is 0 to 3 (at most \377), else two.
        int limit = Math.min(end, start + 1 + (next <= '3' ? 3 : 2));
        int i = start + 1;
        int code = 0;
        while (i < limit && text.charAt(i) >= '0' && text.charAt(i) <= '7') {
            code = code * 8 + (text.charAt(i) - '0');
            i++;
        }
        value.append((char) code);
        return i;
    }

    /** ASCII hexadecimal digits only, as Java's Unicode escapes take (not {@link Character#digit}'s others). */
    private static boolean isHex(String digits) {
        for (int i = 0; i < digits.length(); i++) {
            char c = digits.charAt(i);
            if (!(c >= '0' && c <= '9' || c >= 'a' && c <= 'f' || c >= 'A' && c <= 'F')) {
                return false;
            }
        }
        return true;
    }
}
