package masl.cli;

import java.io.Flushable;
import java.io.IOException;
import java.io.PrintStream;
import java.time.Duration;
import java.util.Locale;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.LongFunction;
import java.util.function.LongSupplier;

/**
 * What masl is doing, on standard error, while one piece of work (translating, compiling, a
 * simulated run) has run longer than {@link Settings#after}: on a terminal one line, rewritten in
 * place and erased when the work ends; otherwise a line every {@link Settings#every}, so that a
 * log is not flooded. {@code --quiet} shows nothing. The journal, on standard output, goes through
 * {@link #journal}: a journal write first erases the line on a terminal, and no progress line is
 * printed while a journal line is half written, so the two never mix, even on one terminal or when
 * both streams go to one file.
 */
final class Progress implements AutoCloseable {

    /**
     * How progress is shown: {@code clock} (nanoseconds), how long work runs before it is shown,
     * how often a line is printed when standard error is not a terminal, whether it is one, and
     * whether to show nothing.
     */
    record Settings(LongSupplier clock, Duration after, Duration every, boolean terminal, boolean quiet) {

        /**
         * A second, five seconds, the system's clock; a terminal when the JVM has a console (Java 17
         * cannot ask about standard error alone: a console means neither standard input nor
         * output is redirected, and then standard error is almost always the same terminal).
         */
        static Settings standard() {
            return new Settings(System::nanoTime, Duration.ofSeconds(1), Duration.ofSeconds(5), System.console() != null, false);
        }

        Settings quiet(boolean silent) {
            return new Settings(clock, after, every, terminal, quiet || silent);
        }
    }

    private static final long TICK_MILLIS = 200;
    /** A terminal's line is rewritten at most this often, however often the work reports its steps. */
    private static final long REDRAW_NANOS = TICK_MILLIS * 1_000_000;
    private static final String ERASE = "\r\033[K";

    private final PrintStream err;
    private final Settings settings;
    private ScheduledExecutorService ticker;
    private LongFunction<String> status;
    private long since;
    private boolean printedOnce;
    private long lastLine;
    private boolean lineShown;
    private boolean journalMidLine;
    private long journalLines;

    Progress(PrintStream err, Settings settings) {
        this.err = err;
        this.settings = settings;
    }

    /** Starts a piece of work; {@code status} gives its line from the time it has run, in nanoseconds. */
    synchronized void begin(LongFunction<String> status) {
        if (settings.quiet()) {
            return;
        }
        this.status = status;
        since = settings.clock().getAsLong();
        printedOnce = false;
        if (ticker == null) {
            ticker = Executors.newSingleThreadScheduledExecutor(run -> {
                Thread thread = new Thread(run, "masl-progress");
                thread.setDaemon(true);
                return thread;
            });
            ticker.scheduleAtFixedRate(this::tick, TICK_MILLIS, TICK_MILLIS, TimeUnit.MILLISECONDS);
        }
    }

    /** The piece of work is over: its line is erased from a terminal. */
    synchronized void end() {
        status = null;
        erase();
    }

    /** Shows the status if the work has run long enough; called by a timer, and by work that reports its own steps. */
    synchronized void tick() {
        if (status == null || journalMidLine) {
            return;
        }
        long now = settings.clock().getAsLong();
        long elapsed = now - since;
        if (elapsed < settings.after().toNanos()) {
            return;
        }
        long period = settings.terminal() ? REDRAW_NANOS : settings.every().toNanos();
        if (printedOnce && now - lastLine < period) {
            return;
        }
        if (settings.terminal()) {
            err.print("\r" + status.apply(elapsed) + "\033[K");
            lineShown = true;
        } else {
            err.println(status.apply(elapsed));
        }
        err.flush();
        printedOnce = true;
        lastLine = now;
    }

    /** How many whole lines the journal has written through {@link #journal}. */
    synchronized long journalLines() {
        return journalLines;
    }

    /** {@code out} for the journal: each write erases the progress line first and is flushed at once. */
    <T extends Appendable & Flushable> Appendable journal(T out) {
        return new JournalSink<>(out);
    }

    private void erase() {
        if (lineShown) {
            err.print(ERASE);
            err.flush();
            lineShown = false;
        }
    }

    @Override
    public synchronized void close() {
        end();
        if (ticker != null) {
            ticker.shutdownNow();
        }
    }

    /** Seconds for a status line: {@code 12.3 s}. */
    static String seconds(long nanos) {
        return String.format(Locale.ROOT, "%.1f s", nanos / 1e9);
    }

    private final class JournalSink<T extends Appendable & Flushable> implements Appendable, Flushable {
        private final T out;

        JournalSink(T out) {
            this.out = out;
        }

        @Override
        public Appendable append(CharSequence text) throws IOException {
            CharSequence written = text == null ? "null" : text;
            synchronized (Progress.this) {
                erase();
                out.append(written);
                out.flush();
                for (int i = 0; i < written.length(); i++) {
                    if (written.charAt(i) == '\n') {
                        journalLines++;
                    }
                }
                if (written.length() > 0) {
                    journalMidLine = written.charAt(written.length() - 1) != '\n';
                }
            }
            return this;
        }

        @Override
        public Appendable append(CharSequence text, int start, int end) throws IOException {
            return append((text == null ? "null" : text).subSequence(start, end));
        }

        @Override
        public Appendable append(char c) throws IOException {
            return append(String.valueOf(c));
        }

        @Override
        public void flush() throws IOException {
            out.flush();
        }
    }
}
