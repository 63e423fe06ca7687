package masl.translator.analysis;

import java.io.IOException;
import java.lang.reflect.Modifier;
import java.net.URI;
import java.nio.file.FileSystem;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

/**
 * The simple names of the public top-level classes of {@code java.lang} and {@code java.util}, the
 * packages a MASL program names without importing them (MASL §4): the candidates of a hint for a
 * misspelt type. Read once, when a hint is first wanted, from the running JDK's image.
 */
final class JavaLibraryNames {

    private static final List<String> PACKAGES = List.of("java/lang", "java/util");
    private static Set<String> names;

    private JavaLibraryNames() {
    }

    static synchronized Set<String> simpleNames() {
        if (names == null) {
            names = read();
        }
        return names;
    }

    private static Set<String> read() {
        Set<String> found = new TreeSet<>();
        try {
            FileSystem image = FileSystems.getFileSystem(URI.create("jrt:/"));
            for (String folder : PACKAGES) {
                try (Stream<Path> classes = Files.list(image.getPath("modules", "java.base", folder))) {
                    classes.map(file -> file.getFileName().toString())
                            .filter(file -> file.endsWith(".class") && !file.contains("$"))
                            .map(file -> file.substring(0, file.length() - ".class".length()))
                            .filter(name -> isPublic(folder.replace('/', '.') + "." + name))
                            .forEach(found::add);
                }
            }
        } catch (IOException | RuntimeException noImage) {
            // without a readable image a hint only has fewer candidates
        }
        return found;
    }

    private static boolean isPublic(String className) {
        try {
            return Modifier.isPublic(Class.forName(className, false, JavaLibraryNames.class.getClassLoader()).getModifiers());
        } catch (ClassNotFoundException | LinkageError notLoadable) {
            return false;
        }
    }
}
