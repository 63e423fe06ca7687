package masl.runtime.diagnostic;

/** How bad a {@link Diagnostic} is: an error stops what reads the input; a warning lets it go on. */
public enum Severity {
    ERROR("error"), WARNING("warning");

    private final String word;

    Severity(String word) {
        this.word = word;
    }

    /** The word printed after the position: {@code error} or {@code warning}. */
    public String word() {
        return word;
    }
}
