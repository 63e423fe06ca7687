package masl.translator.generate;

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

    /** Appends the Java string literal holding {@code text} to {@code out}; returns {@code out}. */
    static StringBuilder quote(StringBuilder out, String text) {
        if (isPlain(text)) {
            return out.append('"').append(text).append('"');
        }
        out.append('"');
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            switch (c) {
                case '"' -> out.append("\\\"");
                case '\\' -> out.append("\\\\");
                case '\n' -> out.append("\\n");
                case '\r' -> out.append("\\r");
                case '\t' -> out.append("\\t");
                default -> {
                    if (c < 0x20 || c > 0x7e) {
                        out.append(String.format("\\u%04x", (int) c));
                    } else {
                        out.append(c);
                    }
                }
            }
        }
        return out.append('"');
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
     * The first line of a construct's source text, shortened, safe inside a {@code //} comment:
     * javac reads unicode escapes even in comments, so {@code \\u} is defused.
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
        StringBuilder safe = new StringBuilder();
        for (char c : text.toCharArray()) {
            safe.append(c < 0x20 || c > 0x7e ? '?' : c);
        }
        return safe.toString().replace("\\u", "\\\\u");
    }

    /** The header of an entry block or a loop: its first line, without the opening brace. */
    static String header(ParserRuleContext tree) {
        String text = snippet(tree);
        int brace = text.lastIndexOf('{');
        return brace > 0 ? text.substring(0, brace).strip() : text;
    }
}
