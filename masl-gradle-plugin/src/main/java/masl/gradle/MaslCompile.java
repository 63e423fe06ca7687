package masl.gradle;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import masl.runtime.descriptor.AgentPath;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.diagnostics.Diagnostic;
import masl.translator.diagnostics.DiagnosticPrinter;
import masl.translator.source.SourceFile;
import org.gradle.api.GradleException;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.FileCollection;
import org.gradle.api.tasks.InputFiles;
import org.gradle.api.tasks.OutputDirectory;
import org.gradle.api.tasks.SourceTask;
import org.gradle.api.tasks.TaskAction;

/**
 * Translates every {@code .masl} file of its source into Java under {@link #getOutputDir()}, in the
 * package {@code masl.generated.<program>}. Its inputs are the programs, the descriptors next to
 * them and the agent path; its output the generated folder, which is emptied first so that a
 * deleted program leaves no stale class. Any error in a program fails the task with the same
 * {@code file:line:col} diagnostics as the {@code masl} command, every program's errors in one run.
 */
public class MaslCompile extends SourceTask {

    private final ConfigurableFileCollection agentPath = getProject().files();
    private File outputDir;

    @InputFiles
    public FileCollection getAgentPath() {
        return agentPath;
    }

    public void setAgentPath(Object entries) {
        agentPath.setFrom(entries);
    }

    @OutputDirectory
    public File getOutputDir() {
        return outputDir;
    }

    public void setOutputDir(File outputDir) {
        this.outputDir = outputDir;
    }

    @TaskAction
    public void translate() {
        emptyOutputDir();
        Translator translator = new Translator(agentPathOf(agentPath));
        Map<String, String> texts = new LinkedHashMap<>();
        List<Diagnostic> errors = new ArrayList<>();
        for (File file : getSource().getFiles()) {
            if (!file.getName().endsWith(".masl")) {
                continue;
            }
            SourceFile source = read(file);
            texts.put(source.name(), source.text());
            Translation translation = translator.translate(source);
            if (translation.succeeded()) {
                translation.javaSources().forEach(this::write);
            } else {
                errors.addAll(translation.diagnostics().sorted());
            }
        }
        if (!errors.isEmpty()) {
            throw new GradleException("MASL translation failed:\n" + new DiagnosticPrinter(texts).report(errors));
        }
    }

    static AgentPath agentPathOf(FileCollection entries) {
        List<Path> paths = entries.getFiles().stream().map(File::toPath).toList();
        return AgentPath.of(paths, MaslCompile.class.getClassLoader());
    }

    /** The program, named relative to the project as a user would type it in a shell there. */
    private SourceFile read(File file) {
        try {
            SourceFile absolute = SourceFile.read(file.toPath());
            return new SourceFile(getProject().relativePath(file), absolute.folder(), absolute.text());
        } catch (IOException unreadable) {
            throw new GradleException(getProject().relativePath(file) + ": cannot be read (" + unreadable.getMessage() + ")");
        }
    }

    private void write(String className, String javaSource) {
        Path target = outputDir.toPath().resolve(className.replace('.', File.separatorChar) + ".java");
        try {
            Files.createDirectories(target.getParent());
            Files.writeString(target, javaSource, StandardCharsets.UTF_8);
        } catch (IOException failed) {
            throw new UncheckedIOException("cannot write " + target, failed);
        }
    }

    private void emptyOutputDir() {
        Path root = outputDir.toPath();
        if (!Files.isDirectory(root)) {
            return;
        }
        try (Stream<Path> old = Files.walk(root)) {
            old.sorted((a, b) -> b.getNameCount() - a.getNameCount())
                    .filter(path -> !path.equals(root))
                    .forEach(MaslCompile::delete);
        } catch (IOException failed) {
            throw new UncheckedIOException("cannot empty " + root, failed);
        }
    }

    private static void delete(Path path) {
        try {
            Files.delete(path);
        } catch (IOException failed) {
            throw new UncheckedIOException("cannot delete " + path, failed);
        }
    }
}
