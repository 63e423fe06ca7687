package masl.translator.cache;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HexFormat;
import java.util.List;
import java.util.TreeSet;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentPath;
import masl.translator.MaslClassPath;
import masl.translator.Translator;
import masl.translator.source.SourceFile;

/**
 * The key of a compiled mission: a SHA-256 of everything its translation and compilation could have
 * read (docs/decisions.md, "The cache of compiled missions"):
 *
 * <ul>
 *   <li>masl itself and the JDK: the version of the JVM, and the size and time of last change of
 *       every jar and class file on the class path javac compiles against (masl's, trusted: a
 *       rebuilt or updated masl changes them);</li>
 *   <li>the program: its name, folder and text;</li>
 *   <li>the descriptors: the bytes of every {@code .xml} file directly in the program's folder and
 *       in each folder the program names a descriptor path in (an import or type may name one
 *       anywhere), and the bytes of every file of the agent path (its folders recursively, its
 *       jars): where descriptors, their supertypes and the agent classes javac compiles against are
 *       looked up. The shipped descriptors are part of masl's jars.</li>
 * </ul>
 */
final class MissionKey {

    private static final String FORMAT = "masl compiled mission 1";
    private static byte[] installation;

    private MissionKey() {
    }

    /** The key of {@code source} translated along {@code agentPath}, as it is now on disk. */
    static String of(SourceFile source, AgentPath agentPath) throws IOException {
        Fingerprint key = new Fingerprint().add(FORMAT).add(installation());
        key.add(source.name()).add(String.valueOf(source.folder())).add(source.text());
        for (Path folder : MissionInputs.descriptorFolders(source)) {
            key.add(folder.toString());
            for (Path file : MissionInputs.xmlFilesIn(folder)) {
                key.add(file.getFileName().toString()).addContent(file);
            }
        }
        for (Path entry : agentPath.entries()) {
            key.add(entry.toAbsolutePath().toString());
            if (Files.isDirectory(entry)) {
                for (Path file : Fingerprint.filesUnder(entry)) {
                    key.add(entry.relativize(file).toString()).addContent(file);
                }
            } else {
                key.addContent(entry);
            }
        }
        return HexFormat.of().formatHex(key.digest());
    }

    /** masl's own classes, the shipped agents and the JDK, once per process. */
    private static synchronized byte[] installation() throws IOException {
        if (installation == null) {
            Fingerprint fingerprint = new Fingerprint().add(Runtime.version().toString())
                    .add(System.getProperty("java.vm.name", "")).add(System.getProperty("java.home", ""));
            TreeSet<String> entries = new TreeSet<>(MaslClassPath.runtimeAndShippedAgents());
            for (String entry : System.getProperty("java.class.path", "").split(File.pathSeparator)) {
                if (!entry.isBlank()) {
                    entries.add(entry);
                }
            }
            MaslClassPath.locationOf(Translator.class).ifPresent(entries::add);
            MaslClassPath.locationOf(MissionProgram.class).ifPresent(entries::add);
            for (String entry : entries) {
                Path path = Path.of(entry).toAbsolutePath();
                fingerprint.add(path.toString());
                List<Path> files = Files.isDirectory(path) ? Fingerprint.filesUnder(path) : List.of(path);
                for (Path file : files) {
                    fingerprint.add(file.toString()).addStamp(file);
                }
            }
            installation = fingerprint.digest();
        }
        return installation;
    }
}
