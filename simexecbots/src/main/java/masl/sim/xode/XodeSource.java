package masl.sim.xode;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import masl.runtime.diagnostic.Severity;

/**
 * Where an XODE document comes from, and the name its messages use. Documents are read as UTF-8
 * (a byte-order mark is skipped); undecodable bytes become U+FFFD, so odd bytes surface as XML errors.
 */
public final class XodeSource {

    /** Produces the raw bytes; may fail with an IOException. */
    @FunctionalInterface
    private interface ByteSupplier {
        byte[] get() throws IOException;
    }

    private final String name;
    private final ByteSupplier bytes;
    /** The file it is read from; null for a resource or text in memory. */
    private final Path file;

    private XodeSource(String name, ByteSupplier bytes) {
        this(name, bytes, null);
    }

    private XodeSource(String name, ByteSupplier bytes, Path file) {
        this.name = name;
        this.bytes = bytes;
        this.file = file;
    }

    /** A file; messages name it as given. */
    public static XodeSource file(Path path) {
        return new XodeSource(path.toString(), () -> Files.readAllBytes(path), path);
    }

    /** A class-path resource such as {@code masl/agents/robots/wheeled-robot.xode}. */
    public static XodeSource resource(String resourcePath) {
        return new XodeSource(resourcePath, () -> {
            try (InputStream in = XodeSource.class.getClassLoader().getResourceAsStream(resourcePath)) {
                if (in == null) {
                    throw new IOException("no such resource on the class path");
                }
                return in.readAllBytes();
            }
        });
    }

    /** In-memory text, named {@code name} in messages. */
    public static XodeSource text(String name, String xml) {
        return new XodeSource(name, () -> xml.getBytes(StandardCharsets.UTF_8));
    }

    /** In-memory bytes, named {@code name} in messages. */
    public static XodeSource bytes(String name, byte[] content) {
        byte[] copy = content.clone();
        return new XodeSource(name, () -> copy);
    }

    public String name() {
        return name;
    }

    /** The file it is read from, when it is one (not a resource, not text in memory). */
    public Optional<Path> file() {
        return Optional.ofNullable(file);
    }

    String readText() throws XodeException {
        try {
            String text = new String(bytes.get(), StandardCharsets.UTF_8);
            return text.startsWith("\uFEFF") ? text.substring(1) : text;
        } catch (IOException e) {
            throw new XodeException(List.of(new XodeProblem(Severity.ERROR, new SourceLocation(name, 1, 1), "",
                    "cannot read the file: " + e.getMessage())));
        }
    }
}
