package masl.runtime.descriptor;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import masl.runtime.diagnostic.Diagnostic;

/** The problems found in one descriptor file, collected as the checks go. */
final class Problems {

    private final String file;
    private final List<Diagnostic> found = new ArrayList<>();

    Problems(String file) {
        this.file = file;
    }

    String file() {
        return file;
    }

    /** A problem at {@code element}; the message starts with how the element is named. */
    void at(XmlElement element, String message) {
        at(element.line(), element.column(), element.describe() + ": " + message);
    }

    void at(int line, int column, String message) {
        found.add(Diagnostic.error(file, line, column, message));
    }

    void addAll(List<Diagnostic> problems) {
        found.addAll(problems);
    }

    boolean isEmpty() {
        return found.isEmpty();
    }

    /**
     * This file's problems sorted by position (stable: at one position they keep the finding order),
     * then those of other files (a supertype's) in the order they were added.
     */
    List<Diagnostic> inFileOrder() {
        List<Diagnostic> sorted = new ArrayList<>();
        found.stream().filter(problem -> problem.file().equals(file))
                .sorted(Comparator.comparingInt(Diagnostic::line).thenComparingInt(Diagnostic::column))
                .forEach(sorted::add);
        found.stream().filter(problem -> !problem.file().equals(file)).forEach(sorted::add);
        return sorted;
    }

    /** @throws DescriptorException with every problem, when there is any */
    void throwIfAny() {
        if (!found.isEmpty()) {
            throw new DescriptorException(inFileOrder());
        }
    }
}
