package masl.gradle;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import org.gradle.api.logging.Logger;

/**
 * Sends what is written to it to a Gradle logger at the {@code quiet} level, one line at a time, so
 * a journal appears as it is written, even under {@code gradle -q}. Agents write from several
 * threads; the journal's own appends are atomic, and this stream serialises them.
 */
final class LineLogger extends OutputStream {

    private final Logger logger;
    private final ByteArrayOutputStream line = new ByteArrayOutputStream();

    LineLogger(Logger logger) {
        this.logger = logger;
    }

    @Override
    public synchronized void write(int b) {
        if (b == '\n') {
            emit();
        } else {
            line.write(b);
        }
    }

    @Override
    public synchronized void close() {
        if (line.size() > 0) {
            emit();
        }
    }

    private void emit() {
        logger.quiet(line.toString(StandardCharsets.UTF_8));
        line.reset();
    }
}
