package masl.jade.platform;

import java.io.OutputStream;
import java.io.PrintStream;
import java.util.List;
import java.util.Optional;
import java.util.function.Supplier;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Where JADE's own log records go: one line each on standard error, {@code JADE <level>: <message>},
 * the first line of the message only and never a stack trace (JADE attaches one to most failures it
 * logs, which a user of {@code masl run} must not see). Records below the chosen level are dropped.
 * What JADE logs of a container that left abruptly is said as masl says it ({@link ContainerDepartures}).
 * A message that reached a container after its addressee left is not logged there: its sender is
 * answered {@code FAILURE} and says what that means ({@link #toldToTheSender}).
 */
final class JadeLog {

    /**
     * JADE's loggers: its packages', and those its system agents name after themselves. Held
     * strongly: java.util.logging keeps loggers weakly, and would forget their settings.
     */
    private static final List<Logger> LOGGERS = Stream.of("jade", "ams", "df").map(Logger::getLogger).toList();

    /**
     * What JADE 4.3's messaging service logs, at warning level, on the container where a message
     * arrived for an agent that has left it: {@code Error serving H-Command
     * jade.core.messaging.Messaging/1: jade.core.NotFoundException: Messaging service slice failed to
     * find ( agent-identifier :name … )}.
     */
    private static final Pattern ADDRESSEE_LEFT = Pattern.compile(
            "Error serving H-Command jade\\.core\\.messaging\\.Messaging/\\d+: jade\\.core\\.NotFoundException:"
                    + " Messaging service slice failed to find .*");

    private static volatile boolean silenced;

    static {
        Handler handler = new OneLineHandler(System.err);
        for (Logger logger : LOGGERS) {
            logger.setUseParentHandlers(false);
            logger.addHandler(handler);
        }
    }

    private JadeLog() {
    }

    /**
     * Whether {@code line}, the first line of a log record, tells of a message that found its
     * addressee gone, which the message's sender hears of as a {@code FAILURE} answer and reports
     * itself. A serving container meets one whenever a mission's coordinator makes sure that it has
     * left (it asks the container's agent, gone by then, whether it is there).
     */
    static boolean toldToTheSender(String line) {
        return ADDRESSEE_LEFT.matcher(line).matches();
    }

    static void setLevel(Level level) {
        LOGGERS.forEach(logger -> logger.setLevel(level));
    }

    /**
     * Runs {@code action} with JADE's log records and standard error out of sight. For a call whose
     * failure JADE reports in both (a log record, then stack traces printed straight to
     * {@code System.err}) while the caller reports it in one line of its own. Only while nothing
     * else of this JVM writes to standard error: at a platform's start.
     */
    static <T> T silenced(Supplier<T> action) {
        PrintStream standardError = System.err;
        silenced = true;
        System.setErr(new PrintStream(OutputStream.nullOutputStream()));
        try {
            return action.get();
        } finally {
            System.setErr(standardError);
            silenced = false;
        }
    }

    private static final class OneLineHandler extends Handler {
        private final PrintStream out;

        OneLineHandler(PrintStream out) {
            this.out = out;
        }

        @Override
        public void publish(LogRecord record) {
            if (silenced) {
                return;
            }
            String message = record.getMessage() == null ? "" : record.getMessage().strip();
            int newline = message.indexOf('\n');
            String first = newline < 0 ? message : message.substring(0, newline);
            if (toldToTheSender(first)) {
                return;
            }
            Optional<String> departure = ContainerDepartures.inMaslWords(first);
            if (departure.isEmpty()) {
                out.println("JADE " + record.getLevel().getName().toLowerCase() + ": " + first);
            } else if (!departure.get().isEmpty()) {
                out.println(departure.get());
            }
        }

        @Override
        public void flush() {
            out.flush();
        }

        @Override
        public void close() {
            flush();
        }
    }
}
