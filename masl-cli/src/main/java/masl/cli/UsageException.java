package masl.cli;

/** The command line itself is wrong: the user gets the message and the usage, exit status 64. */
final class UsageException extends Exception {
    UsageException(String message) {
        super(message);
    }
}
