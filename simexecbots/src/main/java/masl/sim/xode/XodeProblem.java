package masl.sim.xode;

import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.diagnostic.Severity;

/**
 * One problem found in an XODE file: where, in which element, and what.
 *
 * @param severity whether loading can go on (errors stop the load; warnings are kept in the loaded model)
 * @param location where the offending element (or token) starts
 * @param element  the element's name, or an empty string when the XML itself is broken
 * @param message  a sentence for a person, without location
 */
public record XodeProblem(Severity severity, SourceLocation location, String element, String message) {

    /** The problem as every input's problems are shown, the message starting with the element's name. */
    public Diagnostic diagnostic() {
        String where = element.isEmpty() ? "" : "<" + element + ">: ";
        return new Diagnostic(location.file(), location.line(), location.column(), severity, where + message);
    }

    /** Returns {@code file:line:column: error: <element>: message}. */
    public String format() {
        return diagnostic().headline();
    }

    @Override
    public String toString() {
        return format();
    }
}
