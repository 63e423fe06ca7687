package masl.translator.cache;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFileAttributes;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import masl.runtime.descriptor.AgentPath;
import masl.translator.source.SourceFile;

/**
 * The compiled missions of earlier runs, so that running an unchanged program again skips
 * translating and compiling it (the threat model is in docs/decisions.md, "The cache of
 * compiled missions"). An entry is found by its {@link MissionKey}, a digest of everything the
 * translation read, so a changed program, descriptor, agent class, masl or JDK finds no entry. An
 * entry is written whole to a temporary file and renamed into place, so readers, and other masl
 * processes writing the same entry, never see half of one; it ends with the SHA-256 of its bytes and
 * repeats its key, and one that does not match them is not used (and is overwritten by the next
 * store). A folder that someone else could write into is not used at all.
 */
public final class CompiledMissionCache {

    private static final String MAGIC = "masl compiled mission cache 1";
    private static final int DIGEST_BYTES = 32;
    /** A bound on what is read: no generated program comes near it. */
    private static final long MAX_ENTRY_BYTES = 512L << 20;

    private final Path folder;

    public CompiledMissionCache(Path folder) {
        this.folder = folder.toAbsolutePath();
    }

    /** Where the cache lives: {@code $MASL_CACHE_DIR}, else {@code $XDG_CACHE_HOME/masl}, else {@code ~/.cache/masl}. */
    public static Path defaultFolder(Map<String, String> environment) {
        String explicit = environment.get("MASL_CACHE_DIR");
        if (explicit != null && !explicit.isBlank()) {
            return Path.of(explicit);
        }
        String xdg = environment.get("XDG_CACHE_HOME");
        if (xdg != null && !xdg.isBlank() && Path.of(xdg).isAbsolute()) {
            return Path.of(xdg, "masl");
        }
        return Path.of(System.getProperty("user.home"), ".cache", "masl");
    }

    public Path folder() {
        return folder;
    }

    /**
     * Why this cache is not used, if it is not: its folder is not a folder of this user's that only
     * they can write into, or it is a symbolic link.
     */
    public Optional<String> unusable() {
        if (!Files.exists(folder, LinkOption.NOFOLLOW_LINKS)) {
            return Optional.empty();
        }
        try {
            // The link itself is checked, never what it points to: whoever can change the link chooses the folder.
            if (Files.isSymbolicLink(folder)) {
                return Optional.of(folder + " is a symbolic link, not a folder of its own");
            }
            if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
                return Optional.of(folder + " is not a folder");
            }
            PosixFileAttributes attributes = Files.readAttributes(folder, PosixFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
            String owner = attributes.owner().getName();
            if (!owner.equals(System.getProperty("user.name"))) {
                return Optional.of(folder + " belongs to " + owner);
            }
            Set<PosixFilePermission> permissions = attributes.permissions();
            if (permissions.contains(PosixFilePermission.GROUP_WRITE) || permissions.contains(PosixFilePermission.OTHERS_WRITE)) {
                return Optional.of(folder + " can be written by other users");
            }
            return Optional.empty();
        } catch (UnsupportedOperationException notPosix) {
            return Optional.empty();
        } catch (IOException unreadable) {
            return Optional.of(folder + " cannot be read: " + unreadable.getMessage());
        }
    }

    /** The key of {@code source} along {@code agentPath}, as things are now; null when they cannot be read. */
    public String keyOf(SourceFile source, AgentPath agentPath) {
        try {
            return MissionKey.of(source, agentPath);
        } catch (IOException | RuntimeException unreadable) {
            return null;
        }
    }

    /** The entry stored under {@code key}, if there is one, intact, and the cache is usable. */
    public Optional<CompiledMission> lookup(String key) {
        if (key == null || unusable().isPresent()) {
            return Optional.empty();
        }
        Path entry = folder.resolve(key + ".mission");
        try {
            if (!Files.isRegularFile(entry) || Files.size(entry) > MAX_ENTRY_BYTES) {
                return Optional.empty();
            }
            return decode(Files.readAllBytes(entry), key);
        } catch (IOException | RuntimeException unreadable) {
            return Optional.empty();
        }
    }

    /**
     * Stores {@code mission} under {@code key}, replacing what was there; a cache that cannot be
     * written is skipped silently, as a miss is: the run does not depend on it.
     */
    public void store(String key, CompiledMission mission) {
        if (key == null || unusable().isPresent()) {
            return;
        }
        Path temporary = null;
        try {
            createFolder();
            temporary = Files.createTempFile(folder, key, ".partial");
            Files.write(temporary, encode(key, mission));
            moveIntoPlace(temporary, folder.resolve(key + ".mission"));
        } catch (IOException | RuntimeException cannotWrite) {
            deleteQuietly(temporary);
        }
    }

    private void createFolder() throws IOException {
        if (Files.isDirectory(folder)) {
            return;
        }
        try {
            Files.createDirectories(folder.getParent());
            Files.createDirectory(folder, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
        } catch (FileAlreadyExistsException anotherProcess) {
            // created meanwhile by another masl: checked by unusable() like any folder
        } catch (UnsupportedOperationException notPosix) {
            Files.createDirectories(folder);
        }
    }

    private static void moveIntoPlace(Path temporary, Path entry) throws IOException {
        try {
            Files.move(temporary, entry, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException onlyCopies) {
            deleteQuietly(temporary);
        }
    }

    private static void deleteQuietly(Path file) {
        if (file == null) {
            return;
        }
        try {
            Files.deleteIfExists(file);
        } catch (IOException ignored) {
            // a leftover temporary file is never read: entries are found by their final name only
        }
    }

    static byte[] encode(String key, CompiledMission mission) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        DataOutputStream out = new DataOutputStream(bytes);
        out.writeUTF(MAGIC);
        out.writeUTF(key);
        out.writeUTF(mission.missionClassName());
        writeLong(out, mission.diagnostics());
        out.writeInt(mission.classFiles().size());
        for (Map.Entry<String, byte[]> classFile : mission.classFiles().entrySet()) {
            out.writeUTF(classFile.getKey());
            out.writeInt(classFile.getValue().length);
            out.write(classFile.getValue());
        }
        out.flush();
        byte[] body = bytes.toByteArray();
        out.write(Fingerprint.sha256(body, body.length));
        out.flush();
        return bytes.toByteArray();
    }

    static Optional<CompiledMission> decode(byte[] entry, String key) throws IOException {
        if (entry.length < DIGEST_BYTES) {
            return Optional.empty();
        }
        int bodyLength = entry.length - DIGEST_BYTES;
        byte[] digest = Fingerprint.sha256(entry, bodyLength);
        if (!Arrays.equals(digest, 0, DIGEST_BYTES, entry, bodyLength, entry.length)) {
            return Optional.empty();
        }
        DataInputStream in = new DataInputStream(new ByteArrayInputStream(entry, 0, bodyLength));
        if (!in.readUTF().equals(MAGIC) || !in.readUTF().equals(key)) {
            return Optional.empty();
        }
        String missionClass = in.readUTF();
        String diagnostics = readLong(in);
        int count = in.readInt();
        Map<String, byte[]> classFiles = new HashMap<>();
        for (int i = 0; i < count; i++) {
            String name = in.readUTF();
            classFiles.put(name, readBytes(in));
        }
        if (in.available() != 0 || !classFiles.containsKey(missionClass)) {
            return Optional.empty();
        }
        return Optional.of(new CompiledMission(missionClass, classFiles, diagnostics));
    }

    /** writeUTF holds 64 KB at most: the diagnostics of a large program may be longer. */
    private static void writeLong(DataOutputStream out, String text) throws IOException {
        byte[] bytes = text.getBytes(java.nio.charset.StandardCharsets.UTF_8);
        out.writeInt(bytes.length);
        out.write(bytes);
    }

    private static String readLong(DataInputStream in) throws IOException {
        return new String(readBytes(in), java.nio.charset.StandardCharsets.UTF_8);
    }

    private static byte[] readBytes(DataInputStream in) throws IOException {
        int length = in.readInt();
        if (length < 0 || length > in.available()) {
            throw new IOException("a length past the end of the entry");
        }
        byte[] bytes = new byte[length];
        in.readFully(bytes);
        return bytes;
    }
}
