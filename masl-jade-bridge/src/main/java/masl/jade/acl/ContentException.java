package masl.jade.acl;

import masl.runtime.diagnostic.Diagnostic;

/**
 * A message a MASL agent cannot understand: content that is not JSON, not an invocation, names an
 * unknown primitive, or has arguments the primitive cannot take; or a message with the wrong
 * performative, language or ontology. The answer to it is {@code NOT_UNDERSTOOD} with
 * {@link #describe()} as the reason.
 */
public final class ContentException extends Exception {
    private static final long serialVersionUID = 1L;

    /** What positions count from: the message content, as in {@code content:1:12: error: …}. */
    public static final String SOURCE = "content";

    private final int line;
    private final int column;

    /** A problem at a 1-based line and column of the content. */
    public ContentException(String message, int line, int column) {
        super(message);
        this.line = line;
        this.column = column;
    }

    /** A problem of the message as a whole (performative, language, ontology): no position. */
    public ContentException(String message) {
        this(message, 0, 0);
    }

    /** 1-based line in the content; 0 when the problem is not in the content. */
    public int line() {
        return line;
    }

    /** 1-based column in the content; 0 when the problem is not in the content. */
    public int column() {
        return column;
    }

    /** {@code content:LINE:COLUMN: error: MESSAGE}, or {@code message: error: MESSAGE} without a position. */
    public String describe() {
        return Diagnostic.error(line > 0 ? SOURCE : "message", line, column, getMessage()).headline();
    }
}
