package masl.runtime;

import java.io.Flushable;
import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * The mission journal (MASL §13): one stream for the whole mission, written by {@code log} and
 * {@code logln}. Each {@link #append} is atomic: never interleaved with another. The text is kept
 * for {@link #text()} and, if a sink was given, written through to it (a {@code PrintStream}, a
 * {@code Writer}: any {@link Appendable}).
 */
public final class Journal {

    private final StringBuilder text = new StringBuilder();
    private final Appendable sink;

    /** A journal kept in memory only. */
    public Journal() {
        this(null);
    }

    public Journal(Appendable sink) {
        this.sink = sink;
    }

    public synchronized void append(String message) {
        text.append(message);
        if (sink != null) {
            try {
                sink.append(message);
            } catch (IOException e) {
                throw new UncheckedIOException("journal sink failed", e);
            }
        }
    }

    /** Everything written so far. */
    public synchronized String text() {
        return text.toString();
    }

    synchronized void flush() {
        if (sink instanceof Flushable flushable) {
            try {
                flushable.flush();
            } catch (IOException e) {
                throw new UncheckedIOException("journal sink failed", e);
            }
        }
    }
}
