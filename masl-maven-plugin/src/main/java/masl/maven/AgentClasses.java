package masl.maven;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.apache.maven.plugin.MojoExecutionException;
import org.apache.maven.plugin.MojoFailureException;

/**
 * The project's own Java, agent classes among it, compiled before the missions are translated. In
 * Maven the missions' Java is generated in {@code generate-sources}, before the compiler plug-in
 * compiles the project: the descriptors beside the missions are checked against agent classes of
 * {@code src/main/java} that are not compiled yet. This compiles them, into a folder of the plug-in's
 * own, for that check only; the compiler plug-in still compiles them with the generated Java.
 */
final class AgentClasses {

    private AgentClasses() {
    }

    /**
     * Compiles the {@code .java} files under {@code sourceRoots} into {@code classesDir} (emptied first)
     * against {@code classPath}.
     *
     * @throws MojoFailureException with javac's errors when the project's Java does not compile
     */
    static void compile(List<Path> sourceRoots, List<Path> classPath, Path classesDir, String encoding)
            throws MojoExecutionException, MojoFailureException {
        Folders.empty(classesDir);
        List<File> sources = javaFiles(sourceRoots);
        if (sources.isEmpty()) {
            return;
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new MojoExecutionException("masl:compile needs a JDK (javax.tools); Maven runs on a JRE");
        }
        DiagnosticCollector<JavaFileObject> problems = new DiagnosticCollector<>();
        try (StandardJavaFileManager files = javac.getStandardFileManager(problems, Locale.ROOT, null)) {
            Files.createDirectories(classesDir);
            List<String> options = List.of("-d", classesDir.toString(),
                    "-classpath", classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)),
                    "-encoding", encoding, "-proc:none", "-nowarn");
            boolean compiled = javac.getTask(null, files, problems, options, null, files.getJavaFileObjectsFromFiles(sources)).call();
            if (!compiled) {
                throw new MojoFailureException("the project's Java does not compile, so the descriptors of its agent types"
                        + " cannot be checked against their classes:\n" + errors(problems));
            }
        } catch (IOException failed) {
            throw new MojoExecutionException("cannot compile the project's Java into " + classesDir, failed);
        }
    }

    private static List<File> javaFiles(List<Path> sourceRoots) {
        List<File> sources = new ArrayList<>();
        for (Path root : sourceRoots) {
            if (!Files.isDirectory(root)) {
                continue;
            }
            try (Stream<Path> files = Files.walk(root)) {
                files.filter(file -> file.toString().endsWith(".java")).sorted().forEach(file -> sources.add(file.toFile()));
            } catch (IOException unreadable) {
                throw new UncheckedIOException("cannot list " + root, unreadable);
            }
        }
        return sources;
    }

    private static String errors(DiagnosticCollector<JavaFileObject> problems) {
        return problems.getDiagnostics().stream()
                .filter(problem -> problem.getKind() == Diagnostic.Kind.ERROR)
                .map(problem -> problem.toString() + "\n")
                .collect(Collectors.joining());
    }
}
