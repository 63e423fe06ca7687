package masl.translator.cache;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import masl.runtime.descriptor.AgentPath;
import masl.translator.source.SourceFile;

/**
 * The files a translation of a program could read besides the program itself: the {@code .xml} files
 * directly in the program's folder and in each folder its text names a descriptor path in (an import
 * or type may name one anywhere), and every file of the agent path (its folders recursively, its
 * jars), where descriptors, their supertypes and the agent classes javac compiles against are looked
 * up. The key of a compiled mission is made of them ({@link MissionKey}), and a command writes over
 * none of them.
 */
public final class MissionInputs {

    /** A descriptor path as the source may write it, quoted or not: a superset of its imports and types. */
    private static final Pattern DESCRIPTOR_PATH = Pattern.compile("\"([^\"]*\\.xml)\"|([^\\s;\"]+\\.xml)");

    private MissionInputs() {
    }

    /** The descriptor files {@code source} could import, as they are now on disk. */
    public static List<Path> descriptors(SourceFile source) throws IOException {
        List<Path> files = new ArrayList<>();
        for (Path folder : descriptorFolders(source)) {
            files.addAll(xmlFilesIn(folder));
        }
        return files;
    }

    /** The files of {@code agentPath}: its folders' files, recursively, and its jars. */
    public static List<Path> agentPathFiles(AgentPath agentPath) throws IOException {
        List<Path> files = new ArrayList<>();
        for (Path entry : agentPath.entries()) {
            files.addAll(Files.isDirectory(entry) ? Fingerprint.filesUnder(entry) : List.of(entry));
        }
        return files;
    }

    /** The program's folder and the folders of the descriptor paths its text names, relative to it or absolute. */
    static TreeSet<Path> descriptorFolders(SourceFile source) {
        TreeSet<Path> folders = new TreeSet<>();
        Path programFolder = source.folder();
        if (programFolder != null) {
            folders.add(programFolder.toAbsolutePath().normalize());
        }
        Matcher paths = DESCRIPTOR_PATH.matcher(source.text());
        while (paths.find()) {
            String written = paths.group(1) != null ? paths.group(1) : paths.group(2);
            try {
                Path path = Path.of(written);
                Path file = path.isAbsolute() || programFolder == null ? path : programFolder.resolve(path);
                Path folder = file.toAbsolutePath().normalize().getParent();
                if (folder != null) {
                    folders.add(folder);
                }
            } catch (InvalidPathException notAPath) {
                // not a file name anywhere: no descriptor can be found under it
            }
        }
        return folders;
    }

    /** The {@code .xml} files directly in {@code folder}, in name order. */
    static List<Path> xmlFilesIn(Path folder) throws IOException {
        if (!Files.isDirectory(folder)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(folder)) {
            return files.filter(file -> file.getFileName().toString().endsWith(".xml") && Files.isRegularFile(file))
                    .sorted().toList();
        }
    }
}
