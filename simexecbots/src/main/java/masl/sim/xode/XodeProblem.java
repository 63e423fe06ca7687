package masl.sim.xode;

/**
 * One problem found in an XODE file: where, in which element, and what.
 *
 * @param severity whether loading can go on
 * @param location where the offending element (or token) starts
 * @param element  the element's name, or an empty string when the XML itself is broken
 * @param message  a sentence for a person, without location
 */
public record XodeProblem(Severity severity, SourceLocation location, String element, String message) {

    /** Errors stop the load; warnings are kept in the loaded model. */
    public enum Severity { ERROR, WARNING }

    /** Returns {@code file:line:column: error: <element>: message}. */
    public String format() {
        String kind = severity == Severity.ERROR ? "error" : "warning";
        String where = element.isEmpty() ? "" : "<" + element + ">: ";
        return location + ": " + kind + ": " + where + message;
    }

    @Override
    public String toString() {
        return format();
    }
}
