package masl.cli.timeline;

import masl.runtime.diagnostic.Diagnostic;

/** A trace file that is not a JSON-lines trace; the message is {@code file:line:column: error: ...}. */
public final class TraceFormatException extends Exception {

    private static final long serialVersionUID = 1L;

    public TraceFormatException(String file, int line, int column, String message) {
        super(Diagnostic.error(file, line, column, message).headline());
    }
}
