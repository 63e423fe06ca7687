package masl.translator.compile;

/** The translator produced Java that does not compile: a bug of masl, not an error of the user's program. */
public final class GeneratedCodeException extends RuntimeException {
    public GeneratedCodeException(String message) {
        super(message);
    }
}
