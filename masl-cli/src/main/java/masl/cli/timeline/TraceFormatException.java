package masl.cli.timeline;

/** A trace file that is not a JSON-lines trace; the message is {@code file:line:column: error: ...}. */
public final class TraceFormatException extends Exception {

    private static final long serialVersionUID = 1L;

    public TraceFormatException(String file, long line, long column, String message) {
        super(file + ":" + line + ":" + column + ": error: " + message);
    }
}
