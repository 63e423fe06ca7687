package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;

/** {@link Progress} on a clock the test moves, ticked by the test: what is printed, and when. */
class ProgressTest {

    private final AtomicLong now = new AtomicLong();
    private final ByteArrayOutputStream errBytes = new ByteArrayOutputStream();
    private final PrintStream err = new PrintStream(errBytes, true, StandardCharsets.UTF_8);
    private final ByteArrayOutputStream outBytes = new ByteArrayOutputStream();
    private final PrintStream out = new PrintStream(outBytes, true, StandardCharsets.UTF_8);

    private Progress progress(boolean terminal, boolean quiet) {
        return new Progress(err, new Progress.Settings(now::get, Duration.ofSeconds(1), Duration.ofSeconds(5), terminal, quiet));
    }

    private void at(double seconds, Progress progress) {
        now.set(Math.round(seconds * 1e9));
        progress.tick();
    }

    private String err() {
        return errBytes.toString(StandardCharsets.UTF_8);
    }

    @Test
    void nothingUntilASecondThenALineEveryFiveSecondsWhenNotATerminal() {
        try (Progress progress = progress(false, false)) {
            progress.begin(elapsed -> "working " + Progress.seconds(elapsed));
            at(0.5, progress);
            at(0.99, progress);
            assertEquals("", err(), "a short piece of work shows nothing");
            at(1.0, progress);
            at(3.0, progress);
            at(5.9, progress);
            at(6.0, progress);
            progress.end();
            at(20, progress);
        }
        assertEquals("working 1.0 s\nworking 6.0 s\n", err());
    }

    @Test
    void onATerminalOneLineIsRewrittenAndErasedAtTheEnd() {
        try (Progress progress = progress(true, false)) {
            progress.begin(elapsed -> "working " + Progress.seconds(elapsed));
            at(1.2, progress);
            at(1.3, progress);
            at(1.4, progress);
            progress.end();
        }
        assertEquals("\rworking 1.2 s\033[K\rworking 1.4 s\033[K\r\033[K", err(), "rewritten at most five times a second");
    }

    @Test
    void theJournalErasesTheLineAndIsNeverInterruptedMidLine() throws IOException {
        try (Progress progress = progress(true, false)) {
            Appendable journal = progress.journal(out);
            progress.begin(elapsed -> "journal " + progress.journalLines());
            at(1.0, progress);
            journal.append("half a ");
            at(2.0, progress);
            journal.append("line\n");
            at(3.0, progress);
            progress.end();
        }
        assertEquals("half a line\n", outBytes.toString(StandardCharsets.UTF_8));
        assertEquals("\rjournal 0\033[K" + "\r\033[K" + "\rjournal 1\033[K" + "\r\033[K", err(),
                "erased before the journal writes, not shown while its line is half written");
    }

    @Test
    void quietShowsNothing() {
        try (Progress progress = progress(true, true)) {
            progress.begin(elapsed -> "working");
            at(10, progress);
            progress.end();
        }
        assertEquals("", err());
    }
}
