package masl.lsp;

import java.util.logging.ConsoleHandler;
import java.util.logging.Formatter;
import java.util.logging.LogRecord;
import java.util.logging.Logger;

/**
 * What LSP4J and the server log goes to standard error one line a record, without the stack traces
 * java.util.logging prints by default: an editor shows the server's standard error to its user, and a
 * message it sent wrong is answered on the protocol, not with a trace of LSP4J's parser.
 */
final class OneLineLog {

    private static final String[] LOGGERS = {"org.eclipse.lsp4j", "masl.lsp"};
    /** Held: java.util.logging keeps its loggers only weakly, and would drop the configuration with them. */
    private static final Logger[] CONFIGURED = new Logger[LOGGERS.length];

    private OneLineLog() {
    }

    static synchronized void install() {
        for (int i = 0; i < LOGGERS.length; i++) {
            if (CONFIGURED[i] != null) {
                continue;
            }
            Logger logger = Logger.getLogger(LOGGERS[i]);
            ConsoleHandler handler = new ConsoleHandler();
            handler.setFormatter(new Formatter() {
                @Override
                public String format(LogRecord record) {
                    String cause = record.getThrown() == null ? "" : " (" + record.getThrown() + ")";
                    return formatMessage(record) + cause + System.lineSeparator();
                }
            });
            logger.setUseParentHandlers(false);
            logger.addHandler(handler);
            CONFIGURED[i] = logger;
        }
    }
}
