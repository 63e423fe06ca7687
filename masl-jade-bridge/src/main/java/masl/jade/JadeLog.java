package masl.jade;

import java.io.PrintStream;
import java.util.List;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import java.util.stream.Stream;

/**
 * Where JADE's own log records go: one line each on standard error, {@code JADE <level>: <message>},
 * the first line of the message only and never a stack trace (JADE attaches one to most failures it
 * logs, which a user of {@code masl run} must not see). Records below the chosen level are dropped.
 */
final class JadeLog {

    /**
     * JADE's loggers: its packages', and those its system agents name after themselves. Held
     * strongly: java.util.logging keeps loggers weakly, and would forget their settings.
     */
    private static final List<Logger> LOGGERS = Stream.of("jade", "ams", "df").map(Logger::getLogger).toList();

    static {
        Handler handler = new OneLineHandler(System.err);
        for (Logger logger : LOGGERS) {
            logger.setUseParentHandlers(false);
            logger.addHandler(handler);
        }
    }

    private JadeLog() {
    }

    static void setLevel(Level level) {
        LOGGERS.forEach(logger -> logger.setLevel(level));
    }

    private static final class OneLineHandler extends Handler {
        private final PrintStream out;

        OneLineHandler(PrintStream out) {
            this.out = out;
        }

        @Override
        public void publish(LogRecord record) {
            String message = record.getMessage() == null ? "" : record.getMessage().strip();
            int newline = message.indexOf('\n');
            out.println("JADE " + record.getLevel().getName().toLowerCase() + ": "
                    + (newline < 0 ? message : message.substring(0, newline)));
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
