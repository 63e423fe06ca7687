package masl.jade.trust;

import jade.lang.acl.ACLMessage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.HexFormat;
import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

/**
 * The secret a mission spanning containers shares between its coordinator and its containers, out
 * of band (a file only they can read): 256 random bits. Every message between the mission's parties
 * (coordinator, containers, bodies: {@link MissionChannel}) carries an HMAC-SHA256 of what it says,
 * who sends it, whom it is for and its sequence number ({@value #PARAMETER}); a party acts on one only
 * if the signature is right (compared in constant time) and its number new ({@link ReplayWindow}).
 * The secret itself never travels on the platform, so an agent that sees the messages can neither
 * sign one of its own nor have one taken twice.
 * Immutable.
 */
public final class MissionSecret {

    /** The user-defined ACL parameter holding a message's signature. */
    static final String PARAMETER = "masl-signature";
    /** The user-defined ACL parameter numbering the messages of one sender to one receiver, 1, 2, …: see {@link ReplayWindow}. */
    static final String SEQUENCE = "masl-sequence";
    private static final String ALGORITHM = "HmacSHA256";
    private static final int BYTES = 32;
    private static final HexFormat HEX = HexFormat.of();

    private final SecretKeySpec key;

    /** Where a container finds its mission's secret when a control message comes. */
    @FunctionalInterface
    public interface Source {
        /** @throws IOException if the secret cannot be had (yet) */
        MissionSecret get() throws IOException;

        /** The secret in {@code file}, read at each call: {@code masl run} may write it after the container started. */
        static Source file(Path file) {
            return () -> readFrom(file);
        }

        /** {@code secret} itself. */
        static Source of(MissionSecret secret) {
            return () -> secret;
        }
    }

    private MissionSecret(byte[] bits) {
        this.key = new SecretKeySpec(bits, ALGORITHM);
    }

    /** A fresh secret from {@link SecureRandom}. */
    public static MissionSecret generate() {
        byte[] bits = new byte[BYTES];
        new SecureRandom().nextBytes(bits);
        return new MissionSecret(bits);
    }

    /**
     * Reads a secret {@link #writeTo} wrote.
     *
     * @throws IOException if the file cannot be read or holds no secret
     */
    public static MissionSecret readFrom(Path file) throws IOException {
        String text = Files.readString(file, StandardCharsets.US_ASCII).strip();
        if (!text.matches("[0-9a-f]{" + 2 * BYTES + "}")) {
            throw new IOException(file + " holds no mission secret (" + 2 * BYTES + " hexadecimal digits)");
        }
        return new MissionSecret(HEX.parseHex(text));
    }

    /**
     * Writes this secret to {@code file}, a new file only its owner can read (created with owner-only
     * permissions where the file system has them, in one write, before any container is told to read
     * it). A file that exists, or a symbolic link, is refused and left as it was: it may be a user's
     * file or the secret of another mission still running. {@link SecretFile#close()} deletes it.
     *
     * @throws IOException if {@code file} exists or cannot be created or written
     */
    public SecretFile writeTo(Path file) throws IOException {
        return SecretFile.create(file, HEX.formatHex(key.getEncoded()) + "\n");
    }

    /**
     * Whether {@code other} has the same bits (compared in constant time): the same mission's secret,
     * read again. Not {@code equals}, lest a secret land in a hash table and its hash code in a log.
     */
    public boolean sameAs(MissionSecret other) {
        return MessageDigest.isEqual(key.getEncoded(), other.key.getEncoded());
    }

    /**
     * Signs {@code message}, the {@code sequence}th message {@code sender} sends {@code receiver}
     * (local names): sets {@value #SEQUENCE} and {@value #PARAMETER}.
     */
    void sign(ACLMessage message, String sender, String receiver, long sequence) {
        message.addUserDefinedParameter(SEQUENCE, Long.toString(sequence));
        message.addUserDefinedParameter(PARAMETER, signature(message, sender, receiver));
    }

    /** Whether {@code message} bears this secret's signature of what it says, from {@code sender} to {@code receiver}. */
    boolean signed(ACLMessage message, String sender, String receiver) {
        String given = message.getUserDefinedParameter(PARAMETER);
        return given != null && MessageDigest.isEqual(given.getBytes(StandardCharsets.US_ASCII),
                signature(message, sender, receiver).getBytes(StandardCharsets.US_ASCII));
    }

    /**
     * The HMAC of the fields that decide what a message does and whom it binds: performative, sender,
     * receiver, sequence number, conversation, {@code reply-with}, {@code in-reply-to} and content,
     * each with its length so that no two messages have the same input.
     */
    private String signature(ACLMessage message, String sender, String receiver) {
        try {
            Mac mac = Mac.getInstance(ALGORITHM);
            mac.init(key);
            for (String field : new String[] {ACLMessage.getPerformative(message.getPerformative()), sender, receiver,
                    message.getUserDefinedParameter(SEQUENCE), message.getConversationId(), message.getReplyWith(),
                    message.getInReplyTo(), message.getContent()}) {
                byte[] bytes = field == null ? new byte[0] : field.getBytes(StandardCharsets.UTF_8);
                mac.update((field == null ? "-1:" : bytes.length + ":").getBytes(StandardCharsets.US_ASCII));
                mac.update(bytes);
            }
            return HEX.formatHex(mac.doFinal());
        } catch (GeneralSecurityException noHmac) {
            throw new IllegalStateException("this JVM cannot compute " + ALGORITHM, noHmac);
        }
    }
}
