package masl.translator.generate;

/**
 * The text of a generated Java file, built line by line into one buffer: a program of thousands of
 * lines becomes tens of thousands of Java lines, which are not worth keeping one by one.
 */
final class JavaLines {

    private final StringBuilder text;

    JavaLines(int capacity) {
        text = new StringBuilder(capacity);
    }

    /** Adds a line; it ends with a newline. */
    JavaLines add(String line) {
        text.append(line).append('\n');
        return this;
    }

    JavaLines addAll(Iterable<String> lines) {
        for (String line : lines) {
            add(line);
        }
        return this;
    }

    /** The buffer itself, for a writer that appends a line in pieces; it ends each line with a newline. */
    StringBuilder buffer() {
        return text;
    }

    /** The text: every line, each followed by a newline. */
    @Override
    public String toString() {
        return text.toString();
    }
}
