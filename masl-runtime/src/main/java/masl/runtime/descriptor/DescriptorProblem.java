package masl.runtime.descriptor;

import java.util.Objects;

/**
 * One error found in an agent type descriptor.
 *
 * @param file    the descriptor as the user knows it: a path, {@code jar!/entry} or {@code classpath:name}
 * @param line    1-based line of the element at fault; 0 when the problem concerns the whole file
 * @param column  1-based column of the element's {@code <}; 0 when unknown
 * @param message what is wrong, naming the element (for example {@code <Member member_id="P9">})
 */
public record DescriptorProblem(String file, int line, int column, String message) {

    public DescriptorProblem {
        Objects.requireNonNull(file, "file");
        Objects.requireNonNull(message, "message");
    }

    /** {@code file:line:column: error: message}, leaving out what is unknown (the translator's format). */
    @Override
    public String toString() {
        StringBuilder text = new StringBuilder(file);
        if (line > 0) {
            text.append(':').append(line);
            if (column > 0) {
                text.append(':').append(column);
            }
        }
        return text.append(": error: ").append(message).toString();
    }
}
