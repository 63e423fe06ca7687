package masl.runtime.diagnostic;

import java.util.Comparator;
import java.util.Objects;

/**
 * One problem found in an input a user wrote — a MASL program, a descriptor, a placement, an ACL
 * message's content, a trace, a scenario, an XODE file — at a position the user can go to. Every
 * module reports its inputs' problems as these, so that all of them read {@code file:line:column:
 * error: message} and sort alike: by file, then line, then column.
 *
 * @param file     the input as the user named it (a path, {@code jar!/entry}, {@code content}, or an
 *                 option and its value, {@code --place a=c2,b})
 * @param line     1-based line, 0 when the whole input is meant or it has no lines (an option's value)
 * @param column   1-based column, 0 when the whole line is meant
 * @param severity whether reading the input can go on
 * @param message  what is wrong, in the user's terms (never a Java exception's text alone)
 */
public record Diagnostic(String file, int line, int column, Severity severity, String message)
        implements Comparable<Diagnostic> {

    private static final Comparator<Diagnostic> POSITION = Comparator.comparing(Diagnostic::file)
            .thenComparingInt(Diagnostic::line).thenComparingInt(Diagnostic::column);

    public Diagnostic {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(severity, "severity");
        Objects.requireNonNull(message, "message");
    }

    public static Diagnostic error(String file, int line, int column, String message) {
        return new Diagnostic(file, line, column, Severity.ERROR, message);
    }

    /**
     * {@code file:line:column: error: message}, leaving out a line or column that is 0; an input of
     * one line, which has columns but no line (an option's value), reads
     * {@code --place a=c2,b: column 6: error: message}.
     */
    public String headline() {
        StringBuilder text = new StringBuilder(file);
        if (line > 0) {
            text.append(':').append(line);
            if (column > 0) {
                text.append(':').append(column);
            }
        } else if (column > 0) {
            text.append(": column ").append(column);
        }
        return text.append(": ").append(severity.word()).append(": ").append(message).toString();
    }

    /** An error at {@code column} of a command-line option's value: {@code --place a=c2,b: column 6: error: …}. */
    public static Diagnostic inOption(String option, String value, int column, String message) {
        return error(option + " " + value, 0, column, message);
    }

    /** The headline: a diagnostic in a message or a log reads as it does on a terminal. */
    @Override
    public String toString() {
        return headline();
    }

    /** By file, then line, then column. */
    @Override
    public int compareTo(Diagnostic other) {
        return POSITION.compare(this, other);
    }
}
