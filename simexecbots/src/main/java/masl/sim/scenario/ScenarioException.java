package masl.sim.scenario;

import java.util.List;

/**
 * A scenario that cannot be loaded or run: every error, one per line, each
 * {@code file:line:column: error: message}.
 */
public final class ScenarioException extends Exception {

    private final List<String> errors;

    /** @param errors located error lines, at least one */
    public ScenarioException(List<String> errors) {
        super(String.join("\n", errors));
        if (errors.isEmpty()) {
            throw new IllegalArgumentException("a scenario exception needs an error");
        }
        this.errors = List.copyOf(errors);
    }

    /** The error lines in file order. */
    public List<String> errors() {
        return errors;
    }
}
