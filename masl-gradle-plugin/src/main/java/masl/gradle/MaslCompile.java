package masl.gradle;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.diagnostic.DiagnosticPrinter;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;
import org.gradle.api.GradleException;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.FileCollection;
import org.gradle.api.tasks.Classpath;
import org.gradle.api.tasks.InputFiles;
import org.gradle.api.tasks.OutputDirectory;
import org.gradle.api.tasks.SourceTask;
import org.gradle.api.tasks.TaskAction;

/**
 * Translates every {@code .masl} file of its source into Java under {@link #getOutputDir()} (package
 * {@code masl.generated.<program>}) and compiles that Java into {@link #getClassesDir()}.
 *
 * <p>It runs after the source set's own Java is compiled, and {@link #getClasspath()} holds those
 * classes: the descriptors of a program are checked against the agent classes written beside it
 * (every declared primitive and attribute, with its signature), and the generated code compiles
 * against them. Its inputs are the programs, the descriptors next to them, the agent path and that
 * class path; its outputs are emptied first so that a deleted program leaves no stale class. Any
 * error in a program or a descriptor fails the task with the same {@code file:line:col} diagnostics
 * as the {@code masl} command, every program's errors in one run.
 */
public class MaslCompile extends SourceTask {

    private final ConfigurableFileCollection agentPath = getProject().files();
    private final ConfigurableFileCollection classpath = getProject().files();
    private final File projectDir = getProject().getProjectDir();
    private File outputDir;
    private File classesDir;

    /** Folders and jars holding descriptors and their classes, searched after a program's folder. */
    @InputFiles
    public FileCollection getAgentPath() {
        return agentPath;
    }

    public void setAgentPath(Object entries) {
        agentPath.setFrom(entries);
    }

    /**
     * The classes the agents' implementations are checked against and the generated code compiles
     * against: the source set's compiled Java and its class path. Descriptors found on it as
     * resources are found as they are at run time, after the agent path.
     */
    @Classpath
    public FileCollection getClasspath() {
        return classpath;
    }

    public void setClasspath(Object entries) {
        classpath.setFrom(entries);
    }

    /** Where the generated Java goes: readable, and named by the errors of javac should masl have a bug. */
    @OutputDirectory
    public File getOutputDir() {
        return outputDir;
    }

    public void setOutputDir(File outputDir) {
        this.outputDir = outputDir;
    }

    @OutputDirectory
    public File getClassesDir() {
        return classesDir;
    }

    public void setClassesDir(File classesDir) {
        this.classesDir = classesDir;
    }

    @TaskAction
    public void translate() {
        empty(outputDir);
        empty(classesDir);
        Map<String, String> texts = new LinkedHashMap<>();
        List<Diagnostic> errors = new ArrayList<>();
        List<File> generated = new ArrayList<>();
        try (URLClassLoader classes = new URLClassLoader(urls(classpath), MaslCompile.class.getClassLoader())) {
            List<Path> entries = agentPath.getFiles().stream().map(File::toPath).toList();
            Translator translator = new Translator(AgentPath.of(entries, classes));
            for (File file : getSource().getFiles()) {
                if (!file.getName().endsWith(".masl")) {
                    continue;
                }
                SourceFile source = read(file);
                texts.put(source.name(), source.text());
                Translation translation = translator.translate(source);
                if (translation.succeeded()) {
                    translation.javaSources().forEach((className, text) -> generated.add(write(className, text)));
                } else {
                    errors.addAll(translation.diagnostics().sorted());
                }
            }
        } catch (IOException cannotClose) {
            throw new UncheckedIOException(cannotClose);
        }
        if (!errors.isEmpty()) {
            throw new GradleException("MASL translation failed:\n" + new DiagnosticPrinter(texts).report(errors));
        }
        if (!generated.isEmpty()) {
            List<File> compileClassPath = new ArrayList<>(classpath.getFiles());
            compileClassPath.addAll(agentPath.getFiles());
            GeneratedJavaCompiler.compile(generated, compileClassPath, classesDir);
        }
    }

    /** The program, named relative to the project as a user would type it in a shell there. */
    private SourceFile read(File file) {
        try {
            SourceFile absolute = SourceFile.read(file.toPath());
            return new SourceFile(ProjectModel.relative(projectDir, file), absolute.folder(), absolute.text());
        } catch (IOException unreadable) {
            throw new GradleException(ProjectModel.relative(projectDir, file) + ": cannot be read (" + unreadable.getMessage() + ")");
        }
    }

    private File write(String className, String javaSource) {
        Path target = outputDir.toPath().resolve(className.replace('.', File.separatorChar) + ".java");
        try {
            Files.createDirectories(target.getParent());
            Files.writeString(target, javaSource, StandardCharsets.UTF_8);
            return target.toFile();
        } catch (IOException failed) {
            throw new UncheckedIOException("cannot write " + target, failed);
        }
    }

    private static URL[] urls(FileCollection files) {
        List<URL> urls = new ArrayList<>();
        for (File file : files.getFiles()) {
            try {
                urls.add(file.toURI().toURL());
            } catch (MalformedURLException notALocation) {
                throw new IllegalArgumentException(file + " is not a class path entry", notALocation);
            }
        }
        return urls.toArray(URL[]::new);
    }

    private static void empty(File folder) {
        Path root = folder.toPath();
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
