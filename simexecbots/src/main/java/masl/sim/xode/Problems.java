package masl.sim.xode;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import masl.runtime.diagnostic.Severity;

/**
 * Collects the problems of one load so that every error of a file is reported at once rather
 * than only the first. In strict mode a warning counts as an error.
 */
final class Problems {

    private final boolean strict;
    private final List<XodeProblem> errors = new ArrayList<>();
    private final List<XodeProblem> warnings = new ArrayList<>();

    Problems(boolean strict) {
        this.strict = strict;
    }

    void error(XodeElement element, String message) {
        errors.add(new XodeProblem(Severity.ERROR, element.location(), element.name(), message));
    }

    /** Something the loader can work around (xode.md §10); an error in strict mode. */
    void warning(XodeElement element, String message) {
        if (strict) {
            error(element, message);
        } else {
            warnings.add(new XodeProblem(Severity.WARNING, element.location(), element.name(), message));
        }
    }

    /** A warning that stays a warning in strict mode (e.g. another 1.0rNN revision, xode.md §10.17). */
    void notice(XodeElement element, String message) {
        warnings.add(new XodeProblem(Severity.WARNING, element.location(), element.name(), message));
    }

    /** @throws XodeException listing every error, in document order, if there is any */
    void throwIfErrors() throws XodeException {
        if (!errors.isEmpty()) {
            List<XodeProblem> sorted = new ArrayList<>(errors);
            sorted.sort(Comparator.comparing(XodeProblem::diagnostic));
            throw new XodeException(sorted);
        }
    }

    List<XodeProblem> warnings() {
        return List.copyOf(warnings);
    }
}
