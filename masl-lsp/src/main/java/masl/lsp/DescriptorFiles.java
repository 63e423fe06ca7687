package masl.lsp;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Optional;
import masl.runtime.descriptor.DescriptorSource;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;

/**
 * Locations in descriptors for go to definition. A descriptor inside a jar (the shipped {@code Default.xml},
 * a robot library on the agent path) is not a file an editor can open: it is copied, once per content, to a
 * folder of the system's temporary directory, and the editor is sent there.
 */
final class DescriptorFiles {

    private static final Path COPIES = Path.of(System.getProperty("java.io.tmpdir"), "masl-lsp-descriptors");

    private DescriptorFiles() {
    }

    /** The 1-based {@code line} and {@code column} of a descriptor as an LSP location (column 0: the line's start). */
    static Optional<Location> location(DescriptorSource source, int line, int column) {
        Optional<Path> file = source.file().or(() -> copy(source));
        Position start = new Position(Math.max(line - 1, 0), Math.max(column - 1, 0));
        return file.map(path -> new Location(path.toUri().toString(), new Range(start, start)));
    }

    private static Optional<Path> copy(DescriptorSource source) {
        try (InputStream in = source.open()) {
            byte[] content = in.readAllBytes();
            String shown = source.displayName();
            String name = shown.substring(Math.max(shown.lastIndexOf('/'), shown.lastIndexOf(':')) + 1)
                    .replaceAll("[^A-Za-z0-9._-]+", "_");
            Path copy = COPIES.resolve(Integer.toHexString(Arrays.hashCode(content))).resolve(name);
            if (!Files.isRegularFile(copy)) {
                Files.createDirectories(copy.getParent());
                Path partial = Files.createTempFile(copy.getParent(), name, ".part");
                Files.write(partial, content);
                Files.move(partial, copy, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
            return Optional.of(copy);
        } catch (IOException | RuntimeException unreadable) {
            return Optional.empty();
        }
    }
}
