package masl.jade.trust;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Objects;
import java.util.Set;

/**
 * The file a coordinator made to hand its mission's secret to its containers ({@link
 * MissionSecret#writeTo}). It is made only where nothing is (never over a user's file or another
 * mission's secret), and {@link #close()} deletes it only while it is still that file: a file put in
 * its place meanwhile is someone else's and stays.
 */
public final class SecretFile implements AutoCloseable {

    private static final String DEFAULT_PREFIX = ".masl-mission-secret-";

    private final Path path;
    private final Object identity;
    private final String text;

    private SecretFile(Path path, Object identity, String text) {
        this.path = path;
        this.identity = identity;
        this.text = text;
    }

    /**
     * The secret file of the mission whose platform's main container listens on {@code mainPort},
     * in {@code folder}: each platform of a machine has its own, so missions run from one folder do
     * not share one, and a container finds its mission's by the port it joins.
     */
    public static Path defaultFor(Path folder, int mainPort) {
        return folder.resolve(DEFAULT_PREFIX + mainPort);
    }

    static SecretFile create(Path path, String text) throws IOException {
        try (OutputStream out = createNew(path)) {
            out.write(text.getBytes(StandardCharsets.US_ASCII));
        } catch (FileAlreadyExistsException taken) {
            throw new IOException("it exists, and the mission's secret is written only to a file the mission"
                    + " creates (another mission's secret? give each mission its own file; a file left by a mission"
                    + " that was killed? delete it)");
        }
        return new SecretFile(path, identity(path), text);
    }

    /** Creates {@code path} exclusively: fails on anything there, a symbolic link (even dangling) included. */
    private static OutputStream createNew(Path path) throws IOException {
        Set<StandardOpenOption> options = Set.of(StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        try {
            return Channels.newOutputStream(Files.newByteChannel(path, options,
                    PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------"))));
        } catch (UnsupportedOperationException noPosix) {
            return Files.newOutputStream(path, options.toArray(StandardOpenOption[]::new));
        }
    }

    /**
     * The file's inode where the file system has them: with its content, what tells this file from
     * one put at its path later (a file system may give a new file the inode of one just deleted).
     */
    private static Object identity(Path path) throws IOException {
        BasicFileAttributes attributes = Files.readAttributes(path, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
        return attributes.fileKey() != null ? attributes.fileKey() : attributes.creationTime();
    }

    /** Where it is. */
    public Path path() {
        return path;
    }

    /** Deletes the file if it is still the one this mission made; otherwise leaves whatever is there. */
    @Override
    public void close() {
        try {
            if (Objects.equals(identity(path), identity)
                    && Files.readString(path, StandardCharsets.US_ASCII).equals(text)) {
                Files.delete(path);
            }
        } catch (IOException goneOrReplaced) {
            // Already gone, or no longer ours to delete: either way nothing of this mission is left.
        }
    }
}
