package masl.sim.xode;

import java.util.List;
import java.util.stream.Collectors;

/**
 * An XODE file could not be loaded. The message lists every error found, one per line, each as
 * {@code file:line:column: error: <element>: message}; it is meant to be shown to the user as is.
 */
public final class XodeException extends Exception {

    private static final long serialVersionUID = 1L;

    private final transient List<XodeProblem> problems;

    /** @param problems the errors (at least one), in document order */
    public XodeException(List<XodeProblem> problems) {
        super(problems.stream().map(XodeProblem::format).collect(Collectors.joining("\n")));
        this.problems = List.copyOf(problems);
    }

    /** The errors that stopped the load, in document order. */
    public List<XodeProblem> problems() {
        return problems;
    }
}
