package masl.translator.generate;

import masl.grammar.MASLParser;
import masl.translator.parse.Literals;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.misc.Interval;

/** Java literals and comments made from MASL source. */
final class JavaText {

    private static final int SNIPPET_LENGTH = 72;

    private JavaText() {
    }

    /** A Java string literal holding {@code text}. */
    static String quote(String text) {
        return quote(new StringBuilder(text.length() + 2), text).toString();
    }

    /**
     * Appends the Java string literal holding {@code text} to {@code out}; returns {@code out}. Every
     * backslash, quote and character outside printable ASCII is escaped, and no Unicode escape stands
     * for a character javac would read as part of the literal's syntax (those have escapes of their
     * own): javac reads back exactly {@code text}.
     */
    static StringBuilder quote(StringBuilder out, String text) {
        if (isPlain(text)) {
            return out.append('"').append(text).append('"');
        }
        StringBuilder literal = new StringBuilder(text.length() + 8).append('"');
        boolean split = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            escaped(literal, c, '"');
            if (Character.isHighSurrogate(c) && i + 1 < text.length() && !Character.isLowSurrogate(text.charAt(i + 1))) {
                // javac 17 misreads a lone high surrogate's escape followed by a backslash: a new literal
                // follows it, the whole a constant in parentheses.
                literal.append("\" + \"");
                split = true;
            }
        }
        literal.append('"');
        return split ? out.append('(').append(literal).append(')') : out.append(literal);
    }

    /** A Java character literal holding {@code c}, escaped as {@link #quote} escapes. */
    static String character(char c) {
        return escaped(new StringBuilder("'"), c, '\'').append('\'').toString();
    }

    /** The Java literal of a MASL literal: a string's or character's from its decoded value, others as written. */
    static String literal(MASLParser.LiteralContext literal) {
        try {
            if (literal.StringLiteral() != null) {
                return quote(Literals.string(literal.getText()));
            }
            if (literal.CharacterLiteral() != null) {
                return character(Literals.character(literal.getText()));
            }
        } catch (Literals.Problem unchecked) {
            throw new IllegalStateException("the parser lets no such literal through: " + literal.getText(), unchecked);
        }
        return literal.getText();
    }

    private static StringBuilder escaped(StringBuilder out, char c, char quote) {
        return switch (c) {
            case '\\' -> out.append("\\\\");
            case '\n' -> out.append("\\n");
            case '\r' -> out.append("\\r");
            case '\t' -> out.append("\\t");
            default -> {
                if (c == quote) {
                    yield out.append('\\').append(c);
                } else if (c < 0x20 || c == 0x7f) {
                    // Three octal digits: no digit after it can extend the escape.
                    yield out.append(String.format("\\%03o", (int) c));
                } else if (c > 0x7f) {
                    yield out.append(String.format("\\u%04x", (int) c));
                } else {
                    yield out.append(c);
                }
            }
        };
    }

    /** Whether {@code text} stands in a string literal as it is: printable ASCII, no quote or backslash. */
    private static boolean isPlain(String text) {
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c < 0x20 || c > 0x7e || c == '"' || c == '\\') {
                return false;
            }
        }
        return true;
    }

    /**
     * {@code text} made safe inside a Java comment, {@code //} or {@code /* *\/}: javac reads Unicode
     * escapes even in comments, so a {@code \\u000a} there would end a line comment and let the rest of
     * the line run. Every backslash is doubled (so none can start a Unicode escape), every character
     * outside printable ASCII is written {@code \\uXXXX} (its backslash doubled as well), and
     * {@code *\/} is broken.
     */
    static String comment(String text) {
        StringBuilder safe = new StringBuilder(text.length());
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c == '\\') {
                safe.append("\\\\");
            } else if (c < 0x20 || c > 0x7e) {
                safe.append(String.format("\\\\u%04x", (int) c));
            } else if (c == '/' && i > 0 && text.charAt(i - 1) == '*') {
                safe.append(' ').append(c);
            } else {
                safe.append(c);
            }
        }
        return safe.toString();
    }

    /**
     * The first line of a construct's source text, shortened: the text of a case's comment (written
     * through {@link #comment}) and of the runtime's reports (written through {@link #quote}).
     */
    static String snippet(ParserRuleContext tree) {
        String text;
        if (tree.getStop() == null || tree.getStop().getStopIndex() < tree.getStart().getStartIndex()) {
            text = tree.getText();
        } else {
            text = tree.getStart().getInputStream()
                    .getText(Interval.of(tree.getStart().getStartIndex(), tree.getStop().getStopIndex()));
        }
        int newline = text.indexOf('\n');
        if (newline >= 0) {
            text = text.substring(0, newline);
        }
        text = text.strip();
        if (text.length() > SNIPPET_LENGTH) {
            text = text.substring(0, SNIPPET_LENGTH) + "...";
        }
        return text;
    }

    /** The header of an entry block or a loop: its first line, without the opening brace. */
    static String header(ParserRuleContext tree) {
        String text = snippet(tree);
        int brace = text.lastIndexOf('{');
        return brace > 0 ? text.substring(0, brace).strip() : text;
    }
}
