package masl.sim.scenario;

import java.util.List;
import java.util.stream.Collectors;
import masl.runtime.diagnostic.Diagnostic;

/**
 * A scenario that cannot be loaded or run: every error, one per line of the message, each
 * {@code file:line:column: error: message}.
 */
public final class ScenarioException extends Exception {

    private final transient List<Diagnostic> diagnostics;

    /** @param diagnostics the errors, at least one, in the order they are to be read */
    public ScenarioException(List<Diagnostic> diagnostics) {
        super(diagnostics.stream().map(Diagnostic::headline).collect(Collectors.joining("\n")));
        if (diagnostics.isEmpty()) {
            throw new IllegalArgumentException("a scenario exception needs an error");
        }
        this.diagnostics = List.copyOf(diagnostics);
    }

    /** The errors in the order they are to be read. */
    public List<Diagnostic> diagnostics() {
        return diagnostics;
    }
}
