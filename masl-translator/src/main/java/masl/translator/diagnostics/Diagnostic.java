package masl.translator.diagnostics;

/**
 * One error found in a MASL program or in a descriptor it uses, at a position a user can go to.
 *
 * @param file the file as the user named it (or as found on the agent path)
 * @param line 1-based line, 0 when the whole file is meant
 * @param column 1-based column, 0 when the whole line is meant
 * @param message what is wrong, in the user's terms (never a Java exception's text alone)
 */
public record Diagnostic(String file, int line, int column, String message) implements Comparable<Diagnostic> {

    /** {@code file:line:column: error: message}, the first line of the rendering. */
    public String headline() {
        StringBuilder text = new StringBuilder(file);
        if (line > 0) {
            text.append(':').append(line);
            if (column > 0) {
                text.append(':').append(column);
            }
        }
        return text.append(": error: ").append(message).toString();
    }

    @Override
    public int compareTo(Diagnostic other) {
        int byFile = file.compareTo(other.file);
        if (byFile != 0) {
            return byFile;
        }
        int byLine = Integer.compare(line, other.line);
        return byLine != 0 ? byLine : Integer.compare(column, other.column);
    }
}
