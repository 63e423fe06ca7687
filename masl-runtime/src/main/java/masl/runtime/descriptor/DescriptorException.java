package masl.runtime.descriptor;

import java.util.List;
import java.util.stream.Collectors;
import masl.runtime.diagnostic.Diagnostic;

/**
 * A descriptor (or a supertype it needs) could not be loaded. Unchecked, so that loading can sit in
 * streams and lambdas; every loading method of {@link DescriptorLoader} documents that it throws it.
 * {@link #problems()} lists every problem found, in file order, never empty.
 */
public class DescriptorException extends RuntimeException {

    private static final long serialVersionUID = 1L;

    private final List<Diagnostic> problems;

    /** @throws IllegalArgumentException if {@code problems} is empty: an error without a problem is a bug */
    public DescriptorException(List<Diagnostic> problems) {
        super(render(problems));
        if (problems.isEmpty()) {
            throw new IllegalArgumentException("a DescriptorException needs at least one problem");
        }
        this.problems = List.copyOf(problems);
    }

    /** The problems, each naming file, line, column and element; at least one. */
    public List<Diagnostic> problems() {
        return problems;
    }

    private static String render(List<Diagnostic> problems) {
        return problems.stream().map(Diagnostic::toString).collect(Collectors.joining("\n"));
    }
}
