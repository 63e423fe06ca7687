package masl.maven;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.stream.Stream;
import org.apache.maven.plugin.MojoExecutionException;

/**
 * The generated Java of a project's missions in its source root. A file whose text is unchanged is
 * left as it is, so that the compiler plug-in does not recompile the project for nothing; a file no
 * program generates any more is deleted, so a deleted program leaves no stale class. Only the
 * generated packages ({@code masl/generated/}) are touched: nothing else a user keeps in the folder.
 */
final class GeneratedSources {

    private final Path root;

    GeneratedSources(Path root) {
        this.root = root;
    }

    /** Writes {@code javaSources} (text by class name) and removes what they no longer hold. */
    void update(Map<String, String> javaSources) throws MojoExecutionException {
        Set<Path> written = new HashSet<>();
        for (Map.Entry<String, String> source : javaSources.entrySet()) {
            Path target = root.resolve(source.getKey().replace('.', File.separatorChar) + ".java");
            written.add(target);
            write(target, source.getValue());
        }
        removeAllBut(written);
    }

    private static void write(Path target, String text) throws MojoExecutionException {
        try {
            if (Files.isRegularFile(target) && Files.readString(target, StandardCharsets.UTF_8).equals(text)) {
                return;
            }
            Files.createDirectories(target.getParent());
            Files.writeString(target, text, StandardCharsets.UTF_8);
        } catch (IOException failed) {
            throw new MojoExecutionException("cannot write " + target, failed);
        }
    }

    private void removeAllBut(Set<Path> kept) throws MojoExecutionException {
        Path generated = root.resolve("masl").resolve("generated");
        if (!Files.isDirectory(generated)) {
            return;
        }
        try (Stream<Path> files = Files.walk(generated)) {
            List<Path> deepestFirst = files.sorted(Comparator.comparingInt(Path::getNameCount).reversed()).toList();
            for (Path path : deepestFirst) {
                if (Files.isDirectory(path) ? isEmpty(path) : !kept.contains(path)) {
                    Files.delete(path);
                }
            }
        } catch (IOException failed) {
            throw new MojoExecutionException("cannot remove the stale sources of " + generated, failed);
        }
    }

    private static boolean isEmpty(Path folder) throws IOException {
        try (Stream<Path> entries = Files.list(folder)) {
            return entries.findAny().isEmpty();
        }
    }
}
