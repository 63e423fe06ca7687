package masl.translator.diagnostics;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import masl.runtime.diagnostic.Diagnostic;

/**
 * Collects every error of a run, so a user sees all of them at once rather than the first only.
 * The same error reported twice at the same place is kept once. Not thread-safe: one per run.
 */
public final class Diagnostics {

    private final Set<Diagnostic> reported = new LinkedHashSet<>();

    public void error(String file, int line, int column, String message) {
        reported.add(Diagnostic.error(file, line, column, message));
    }

    public void add(Diagnostic diagnostic) {
        reported.add(diagnostic);
    }

    public boolean hasErrors() {
        return !reported.isEmpty();
    }

    /** The errors in file, line and column order. */
    public List<Diagnostic> sorted() {
        List<Diagnostic> list = new ArrayList<>(reported);
        Collections.sort(list);
        return list;
    }
}
