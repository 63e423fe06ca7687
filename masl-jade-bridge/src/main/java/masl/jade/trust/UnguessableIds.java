package masl.jade.trust;

import java.security.SecureRandom;
import java.util.Base64;

/**
 * Conversation ids ({@code reply-with}) nobody can guess: 128 bits from {@link SecureRandom}. An
 * answer is matched to its request by {@code in-reply-to}, and JADE does not authenticate the sender
 * field of a message (any agent may set it): the id is what a forged answer cannot produce.
 *
 * <p>Public for the bodies' relays ({@code placement}), whose ids must not be guessed either.
 */
public final class UnguessableIds {

    private static final SecureRandom RANDOM = new SecureRandom();
    private static final Base64.Encoder TEXT = Base64.getUrlEncoder().withoutPadding();

    private UnguessableIds() {
    }

    /** {@code prefix} followed by 22 characters of fresh randomness. */
    public static String next(String prefix) {
        byte[] bits = new byte[16];
        RANDOM.nextBytes(bits);
        return prefix + "-" + TEXT.encodeToString(bits);
    }
}
