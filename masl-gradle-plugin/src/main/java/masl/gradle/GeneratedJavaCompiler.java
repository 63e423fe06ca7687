package masl.gradle;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.gradle.api.GradleException;

/**
 * Compiles the Java the translator generated into class files, with the build JVM's compiler. The
 * programs were checked against their descriptors and the descriptors against the compiled agent
 * classes, so javac rejecting generated code is a bug of masl, reported as such.
 */
final class GeneratedJavaCompiler {

    private GeneratedJavaCompiler() {
    }

    static void compile(List<File> sources, List<File> classPath, File classesDir) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new GradleException("maslCompile needs a JDK (javax.tools), the build runs on a JRE");
        }
        DiagnosticCollector<JavaFileObject> problems = new DiagnosticCollector<>();
        try (StandardJavaFileManager files = javac.getStandardFileManager(problems, Locale.ROOT, null)) {
            List<String> options = List.of("-d", classesDir.getPath(),
                    "-classpath", classPath.stream().map(File::getPath).collect(Collectors.joining(File.pathSeparator)),
                    "--release", "17", "-encoding", "UTF-8", "-proc:none", "-g", "-nowarn");
            StringWriter output = new StringWriter();
            boolean compiled = javac.getTask(output, files, problems, options, null,
                    files.getJavaFileObjectsFromFiles(sources)).call();
            if (!compiled) {
                throw new GradleException("masl: internal error: the Java generated for these programs does not compile;"
                        + " please report it with the programs\n" + errors(problems) + output);
            }
        } catch (IOException cannotClose) {
            throw new UncheckedIOException(cannotClose);
        }
    }

    private static String errors(DiagnosticCollector<JavaFileObject> problems) {
        return problems.getDiagnostics().stream()
                .filter(problem -> problem.getKind() == Diagnostic.Kind.ERROR)
                .map(problem -> problem.toString() + "\n")
                .collect(Collectors.joining());
    }
}
