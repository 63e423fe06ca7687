package masl.cli;

import java.io.Flushable;
import java.io.PrintStream;

/**
 * The journal's way to standard output. A {@link PrintStream} never throws: it only remembers that
 * a write failed (a full disk, {@code > /dev/full}, a closed pipe). So every line is checked as it
 * is written (standard output flushes at each line) and again when the mission flushes its journal;
 * the first failure calls {@link #whenFailed}'s action once, which stops the mission.
 */
final class JournalOutput implements Appendable, Flushable {

    private final PrintStream out;
    private Runnable onFailure = () -> { };
    private boolean failed;

    JournalOutput(PrintStream out) {
        this.out = out;
    }

    /** What to do on the first failed write: stop the mission, whose journal is lost. */
    synchronized void whenFailed(Runnable action) {
        onFailure = action;
        if (failed) {
            action.run();
        }
    }

    synchronized boolean failed() {
        return failed;
    }

    @Override
    public Appendable append(CharSequence text) {
        String line = text.toString();
        out.append(line);
        if (line.indexOf('\n') >= 0) {
            check();
        }
        return this;
    }

    @Override
    public Appendable append(CharSequence text, int start, int end) {
        return append(text.subSequence(start, end));
    }

    @Override
    public Appendable append(char c) {
        return append(String.valueOf(c));
    }

    @Override
    public void flush() {
        check();
    }

    private void check() {
        if (!out.checkError()) {
            return;
        }
        Runnable action;
        synchronized (this) {
            if (failed) {
                return;
            }
            failed = true;
            action = onFailure;
        }
        action.run();
    }
}
