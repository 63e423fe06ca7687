package masl.maven;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;
import org.apache.maven.plugin.MojoExecutionException;

/** The folders the plug-in owns, emptied before it writes them so that nothing stale stays. */
final class Folders {

    private Folders() {
    }

    /** Deletes what {@code folder} holds, deepest first; a folder that does not exist is empty. */
    static void empty(Path folder) throws MojoExecutionException {
        if (!Files.isDirectory(folder)) {
            return;
        }
        try (Stream<Path> old = Files.walk(folder)) {
            for (Path path : old.sorted(Comparator.comparingInt(Path::getNameCount).reversed()).toList()) {
                if (!path.equals(folder)) {
                    Files.delete(path);
                }
            }
        } catch (IOException failed) {
            throw new MojoExecutionException("cannot empty " + folder, failed);
        }
    }
}
