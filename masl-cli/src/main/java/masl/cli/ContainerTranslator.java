package masl.cli;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import masl.jade.placement.DeployedSource;
import masl.jade.placement.ProgramTranslator;
import masl.runtime.descriptor.AgentPath;
import masl.translator.MissionLoader;
import masl.translator.TranslationKey;
import masl.translator.source.SourceFile;

/**
 * How {@code masl container} makes the program of the agents a run deploys to it: the program and
 * the descriptors the run sent are written to a folder of their own, translated and compiled by this
 * masl as {@code masl run} would, along the container's {@code --agent-path} (where the agents'
 * classes come from), with the key of that translation ({@link TranslationKey}). The folder is
 * removed when the container ends.
 */
final class ContainerTranslator implements ProgramTranslator, AutoCloseable {

    /** A file name and nothing else: no folder, no way out of the program's folder. */
    private static final Pattern FILE_NAME = Pattern.compile("[A-Za-z0-9_][A-Za-z0-9_.-]*");

    private final AgentPath agentPath;
    private final List<Path> folders = new ArrayList<>();

    ContainerTranslator(AgentPath agentPath) {
        this.agentPath = agentPath;
    }

    @Override
    public synchronized Translated translate(DeployedSource sent) throws Refusal {
        check(sent.programName(), ".masl");
        for (String descriptor : sent.descriptors().keySet()) {
            check(descriptor, ".xml");
        }
        try {
            Path folder = Files.createTempDirectory("masl-deployed-");
            folders.add(folder);
            Path program = Files.writeString(folder.resolve(sent.programName()), sent.programText());
            for (Map.Entry<String, String> descriptor : sent.descriptors().entrySet()) {
                Files.writeString(folder.resolve(descriptor.getKey()), descriptor.getValue());
            }
            ByteArrayOutputStream diagnostics = new ByteArrayOutputStream();
            Pipeline.Loaded loaded;
            try (PrintStream err = new PrintStream(diagnostics, true, StandardCharsets.UTF_8);
                    Progress quiet = new Progress(err, Progress.Settings.standard().quiet(true))) {
                loaded = Pipeline.load(SourceFile.read(program), agentPath, err, quiet);
            }
            if (loaded == null) {
                throw new Refusal(diagnostics.toString(StandardCharsets.UTF_8).strip()
                        .replace(folder.toString() + File.separator, ""));
            }
            MissionLoader loader = loaded.loader();
            return new Translated(loader.program(), loader::newImplementation,
                    TranslationKey.of(sent.programName(), sent.programText(), sent.descriptors()));
        } catch (IOException unwritable) {
            throw new Refusal("cannot write the program sent here to a folder of its own: " + unwritable.getMessage());
        } catch (MissionLoader.AgentCreationException | IllegalStateException cannotLoad) {
            throw new Refusal(cannotLoad.getMessage());
        }
    }

    private static void check(String name, String extension) throws Refusal {
        if (!FILE_NAME.matcher(name).matches() || !name.endsWith(extension)) {
            throw new Refusal("'" + name + "' is not the name of a " + extension + " file of the program's folder");
        }
    }

    /** Removes the folders the programs were written to. */
    @Override
    public synchronized void close() {
        for (Path folder : folders) {
            try (Stream<Path> files = Files.walk(folder)) {
                for (Path file : files.sorted((one, other) -> other.compareTo(one)).toList()) {
                    Files.deleteIfExists(file);
                }
            } catch (IOException leftBehind) {
                // A temporary folder: the system's cleaning takes it.
            }
        }
        folders.clear();
    }
}
