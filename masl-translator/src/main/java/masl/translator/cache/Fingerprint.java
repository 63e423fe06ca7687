package masl.translator.cache;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.List;
import java.util.stream.Stream;

/** A SHA-256 digest fed with strings, numbers and the contents of files and folders. */
final class Fingerprint {

    private final MessageDigest digest;

    Fingerprint() {
        try {
            digest = MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException impossible) {
            throw new IllegalStateException("every JDK has SHA-256", impossible);
        }
    }

    static byte[] sha256(byte[] bytes, int length) {
        Fingerprint fingerprint = new Fingerprint();
        fingerprint.digest.update(bytes, 0, length);
        return fingerprint.digest();
    }

    /** Adds {@code text}, length-prefixed so that two fields never run into one another. */
    Fingerprint add(String text) {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        add(bytes.length);
        digest.update(bytes);
        return this;
    }

    Fingerprint add(long number) {
        for (int shift = 56; shift >= 0; shift -= 8) {
            digest.update((byte) (number >>> shift));
        }
        return this;
    }

    Fingerprint add(byte[] bytes) {
        add(bytes.length);
        digest.update(bytes);
        return this;
    }

    /** Adds a file's bytes, or a mark that it is absent. */
    Fingerprint addContent(Path file) throws IOException {
        if (!Files.isRegularFile(file)) {
            return add("absent");
        }
        add(Files.size(file));
        byte[] buffer = new byte[65536];
        try (InputStream in = Files.newInputStream(file)) {
            for (int read = in.read(buffer); read >= 0; read = in.read(buffer)) {
                digest.update(buffer, 0, read);
            }
        }
        return this;
    }

    /** Adds a file's size and time of last change (not its bytes): for masl's own, trusted, installation. */
    Fingerprint addStamp(Path file) throws IOException {
        if (!Files.exists(file)) {
            return add("absent");
        }
        return add(Files.size(file)).add(Files.getLastModifiedTime(file).toMillis());
    }

    /** Every regular file below {@code folder}, in name order, by its relative name. */
    static List<Path> filesUnder(Path folder) throws IOException {
        try (Stream<Path> files = Files.walk(folder)) {
            return files.filter(Files::isRegularFile).sorted().toList();
        }
    }

    byte[] digest() {
        return digest.digest();
    }
}
