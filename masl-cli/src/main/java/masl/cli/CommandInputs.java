package masl.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import masl.runtime.descriptor.AgentPath;
import masl.translator.cache.MissionInputs;
import masl.translator.source.SourceFile;

/**
 * The files a command reads (its program, descriptors, agent path, scenario and worlds, trace), so
 * that none of its outputs writes over one of them. A file is known by its identity, not its name:
 * a symbolic link to an input, or a hard link of it, is that input. Checked before anything is
 * written: a refused output leaves every file as it was.
 */
final class CommandInputs {

    /** An input as the user knows it ({@code the program victim.masl}), and its identity. */
    private record Input(String described, Path file, Object key) {
    }

    private final List<Input> inputs = new ArrayList<>();

    /** What translating {@code source} along {@code agentPath} reads: the program, the descriptors it could import, the agent path. */
    static CommandInputs ofProgram(SourceFile source, AgentPath agentPath) {
        return new CommandInputs().add("the program", source.name())
                .addListed("the descriptor", () -> MissionInputs.descriptors(source))
                .addListed("the agent path's file", () -> MissionInputs.agentPathFiles(agentPath));
    }

    /** Files found by looking in folders. */
    private interface Listing {
        List<Path> files() throws IOException;
    }

    /** Adds {@code file}, described as {@code what} ({@code "the program"}), if it exists; a name of nothing reads nothing. */
    CommandInputs add(String what, Path file) {
        if (file != null && Files.exists(file)) {
            inputs.add(new Input(what + " " + file, file, keyOf(file)));
        }
        return this;
    }

    /** Adds the file named {@code name} as {@link #add} does; a name that is no file name names no input. */
    CommandInputs add(String what, String name) {
        Path file = pathOrNull(name);
        return file == null ? this : add(what, file);
    }

    /** Adds each of {@code files} as {@link #add} does. */
    CommandInputs addAll(String what, List<Path> files) {
        files.forEach(file -> add(what, file));
        return this;
    }

    /** Adds the files {@code listing} finds; what cannot be listed cannot be read either: it is no input. */
    private CommandInputs addListed(String what, Listing listing) {
        try {
            return addAll(what, listing.files());
        } catch (IOException | UncheckedIOException unlisted) {
            return this;
        }
    }

    /**
     * Refuses {@code output}, described as {@code what} ({@code "the trace"}), if it is one of the
     * inputs; a file that does not exist yet is none of them.
     *
     * @throws UsageException naming the output and the input it would overwrite
     */
    void refuseOverwriting(String what, Path output) throws UsageException {
        if (!Files.exists(output)) {
            return;
        }
        Object key = keyOf(output);
        for (Input input : inputs) {
            if (key != null && input.key() != null ? key.equals(input.key()) : sameFile(output, input.file())) {
                throw new UsageException(what + " " + output + " is " + input.described()
                        + (output.equals(input.file()) ? "" : " (the same file)")
                        + ": masl does not write over a file it reads");
            }
        }
    }

    /**
     * Refuses a journal written to {@code out} when {@code out} is this process's standard output and
     * that is one of the inputs ({@code masl run p.masl >> p.masl}); Linux names it {@code /dev/stdout}.
     */
    void refuseJournalOverwriting(PrintStream out) throws UsageException {
        Path standardOutput = Path.of("/dev/stdout");
        if (out == System.out && Files.exists(standardOutput)) {
            refuseOverwriting("the journal (standard output)", standardOutput);
        }
    }

    /** As {@link #refuseOverwriting(String, Path)}, for an output named {@code name}, if it is a file name. */
    void refuseOverwriting(String what, String name) throws UsageException {
        Path output = pathOrNull(name);
        if (output != null) {
            refuseOverwriting(what, output);
        }
    }

    private static Path pathOrNull(String name) {
        try {
            return name == null ? null : Path.of(name);
        } catch (InvalidPathException notAFileName) {
            return null;
        }
    }

    /** The file system's identity of {@code file} (device and inode on Unix), following links; null if it has none. */
    private static Object keyOf(Path file) {
        try {
            return Files.readAttributes(file, BasicFileAttributes.class).fileKey();
        } catch (IOException | SecurityException unreadable) {
            return null;
        }
    }

    private static boolean sameFile(Path one, Path other) {
        try {
            return Files.isSameFile(one, other);
        } catch (IOException | SecurityException unreadable) {
            return Objects.equals(one.toAbsolutePath().normalize(), other.toAbsolutePath().normalize());
        }
    }
}
