package masl.sim.xode;

import masl.runtime.diagnostic.Diagnostic;

/**
 * A position in an XODE source: the file's display name, a 1-based line and a 1-based column.
 * Printed as {@code file:line:column}, the form compilers use, so editors can jump to it.
 */
public record SourceLocation(String file, int line, int column) {

    /** An error at this position. */
    public Diagnostic error(String message) {
        return Diagnostic.error(file, line, column, message);
    }

    @Override
    public String toString() {
        return file + ":" + line + ":" + column;
    }
}
