package masl.maven;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/** The MASL programs ({@code *.masl}) under a folder, in a stable order. */
final class Programs {

    private static final String EXTENSION = ".masl";

    private Programs() {
    }

    static List<Path> in(Path folder) {
        if (!Files.isDirectory(folder)) {
            return List.of();
        }
        try (Stream<Path> files = Files.walk(folder)) {
            return files.filter(file -> file.getFileName().toString().endsWith(EXTENSION) && Files.isRegularFile(file))
                    .sorted().toList();
        } catch (IOException unreadable) {
            throw new UncheckedIOException("cannot list " + folder, unreadable);
        }
    }

    /** A program's mission name: its file name without {@code .masl}. */
    static String missionName(Path program) {
        String name = program.getFileName().toString();
        return name.substring(0, name.length() - EXTENSION.length());
    }
}
