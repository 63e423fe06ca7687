package masl.cli;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.Charset;
import java.nio.charset.StandardCharsets;
import java.util.Optional;
import java.util.regex.Pattern;
import masl.jade.platform.ContainerDepartures;

/**
 * A standard error on which every stack trace is one line: its first (the exception and its
 * message); its frames, {@code ... n more}, {@code Caused by:} lines and JADE's own
 * {@code Nested Exception:} lines are dropped. JADE prints some of its faults with
 * {@code printStackTrace} rather than through its log (a peer container whose JVM ended abruptly):
 * the {@code masl} command ({@link Main}) installs it as {@code System.err} so that those are one line
 * too (masl-jade-bridge's {@code JadeLog} makes JADE's log records one line; the CLI itself never
 * prints a stack trace). What JADE prints so of a container that left abruptly is said in masl's
 * words ({@link ContainerDepartures}). An interrupt that JADE's own threads print while the platform
 * shuts down (SIGTERM: its resource manager's terminator interrupted in {@code sleep}) is dropped: the
 * first line of an {@code InterruptedException}'s trace waits for its first frame outside the JDK,
 * and is printed only if that frame is not JADE's. No JADE class is involved: an in-process run loads none.
 * Thread-safe, as a {@link PrintStream} is.
 */
final class StackTraceFolding extends OutputStream {

    private static final Pattern CONTINUATION = Pattern.compile(
            "\\s+at \\S.*|\\s*\\.\\.\\. \\d+ more|\\s*(Caused by|Suppressed): .*|\\s*Nested Exception:\\s*");

    private static final Pattern INTERRUPTED = Pattern.compile("java\\.lang\\.InterruptedException(: .*)?");
    private static final Pattern JDK_FRAME = Pattern.compile("\\s+at (java\\.base/)?(java|jdk|sun)\\..*");
    private static final Pattern JADE_FRAME = Pattern.compile("\\s+at jade\\..*");

    private final PrintStream target;
    private final ByteArrayOutputStream line = new ByteArrayOutputStream();
    /** The first line of an interrupt's trace, until its first frame outside the JDK says whose it is. */
    private byte[] interrupt;

    private StackTraceFolding(PrintStream target) {
        this.target = target;
    }

    /** {@code target}, stack traces folded, flushed at each line; text is encoded in the platform's charset. */
    static PrintStream around(PrintStream target) {
        return new PrintStream(new StackTraceFolding(target), true, Charset.defaultCharset());
    }

    @Override
    public synchronized void write(int b) {
        line.write(b);
        if (b == '\n') {
            // The patterns are ASCII: matching bytes as Latin-1 works for any charset that extends ASCII.
            String text = line.toString(StandardCharsets.ISO_8859_1).stripTrailing();
            // Only JADE's exceptions start so: no class of the bridge is loaded for other lines.
            Optional<String> departure = text.startsWith("jade.") ? ContainerDepartures.inMaslWords(text) : Optional.empty();
            boolean continuation = CONTINUATION.matcher(text).matches();
            if (interrupt != null && !(continuation && JDK_FRAME.matcher(text).matches())) {
                if (!(continuation && JADE_FRAME.matcher(text).matches())) {
                    target.write(interrupt, 0, interrupt.length);
                }
                interrupt = null;
            }
            if (departure.isPresent()) {
                if (!departure.get().isEmpty()) {
                    target.println(departure.get());
                }
            } else if (INTERRUPTED.matcher(text).matches()) {
                interrupt = line.toByteArray();
            } else if (!continuation) {
                target.write(line.toByteArray(), 0, line.size());
            }
            line.reset();
        }
    }

    @Override
    public synchronized void flush() {
        target.flush();
    }
}
