package masl.translator;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Stream;
import masl.grammar.MASLParser;
import masl.runtime.MissionProgram;

/**
 * What two JVMs compare before one runs agents' programs the other translated too (a deployment
 * over JADE containers): a SHA-256 of the masl that translates (the bytes of the translator's, the
 * grammar's, the runtime's and the shipped agents' classes, wherever they are installed), the
 * program's name and text, and each descriptor sent with it (name and text). Equal keys: the same
 * masl translated the same program and descriptors, so the same generated classes run on both sides.
 */
public final class TranslationKey {

    private static final String FORMAT = "masl translation key 1";
    private static byte[] masl;

    private TranslationKey() {
    }

    /** The key of {@code program} (its file name and text) with {@code descriptors} (file name to text). */
    public static String of(String programName, String programText, Map<String, String> descriptors) {
        MessageDigest digest = sha256();
        add(digest, FORMAT);
        digest.update(masl());
        add(digest, programName);
        add(digest, programText);
        for (Map.Entry<String, String> descriptor : new TreeMap<>(descriptors).entrySet()) {
            add(digest, descriptor.getKey());
            add(digest, descriptor.getValue());
        }
        return HexFormat.of().formatHex(digest.digest());
    }

    private static void add(MessageDigest digest, String text) {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        digest.update((byte) (bytes.length >>> 24));
        digest.update((byte) (bytes.length >>> 16));
        digest.update((byte) (bytes.length >>> 8));
        digest.update((byte) bytes.length);
        digest.update(bytes);
    }

    /** The digest of masl's own classes, by content (two installations of one masl give one key), once per process. */
    private static synchronized byte[] masl() {
        if (masl == null) {
            TreeSet<String> locations = new TreeSet<>(MaslClassPath.runtimeAndShippedAgents());
            MaslClassPath.locationOf(Translator.class).ifPresent(locations::add);
            MaslClassPath.locationOf(MASLParser.class).ifPresent(locations::add);
            MaslClassPath.locationOf(MissionProgram.class).ifPresent(locations::add);
            MessageDigest digest = sha256();
            try {
                for (String location : locations) {
                    Path path = Path.of(location);
                    for (Path file : files(path)) {
                        add(digest, Files.isDirectory(path) ? path.relativize(file).toString().replace(File.separatorChar, '/')
                                : file.getFileName().toString());
                        try (InputStream in = Files.newInputStream(file)) {
                            byte[] buffer = new byte[65536];
                            for (int read = in.read(buffer); read >= 0; read = in.read(buffer)) {
                                digest.update(buffer, 0, read);
                            }
                        }
                    }
                }
            } catch (IOException unreadable) {
                throw new IllegalStateException("cannot read masl's own classes: " + unreadable.getMessage(), unreadable);
            }
            masl = digest.digest();
        }
        return masl;
    }

    private static List<Path> files(Path location) throws IOException {
        if (!Files.isDirectory(location)) {
            return Files.isRegularFile(location) ? List.of(location) : List.of();
        }
        try (Stream<Path> files = Files.walk(location)) {
            return files.filter(Files::isRegularFile).sorted().toList();
        }
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException impossible) {
            throw new IllegalStateException("every JDK has SHA-256", impossible);
        }
    }
}
