package masl.translator.compile;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.io.StringWriter;
import java.net.URI;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.FileObject;
import javax.tools.ForwardingJavaFileManager;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * Compiles generated Java sources in memory with {@code javax.tools} and loads the classes.
 * Generated code that javac rejects is a translator bug: it surfaces as {@link GeneratedCodeException},
 * which the command line reports as an internal error, never as javac's output for the user to decode.
 */
public final class InMemoryCompiler {

    /** A generated compilation unit: the binary name of its top-level class and its text. */
    public record Source(String className, String text) { }

    /**
     * The Java the generated code is compiled for: 17, masl's. On a JDK 17 that is the JDK's own API, which
     * javac reads from the running image; {@code --release 17} would make it read the API of 17 from the
     * JDK's {@code ct.sym} instead, a tenth of a first {@code masl run}'s CPU. Other JDKs need it.
     */
    private static final List<String> RELEASE = Runtime.version().feature() == 17 ? List.of() : List.of("--release", "17");

    private final List<String> classPath;

    /** @param classPath folders and jars the generated code compiles against, besides this JVM's class path */
    public InMemoryCompiler(List<String> classPath) {
        this.classPath = List.copyOf(classPath);
    }

    /**
     * Compiles {@code sources} and returns a class loader holding them, child of {@code parent}.
     *
     * @throws GeneratedCodeException if javac reports an error, with javac's messages for the bug report
     */
    public ClassLoader compile(List<Source> sources, ClassLoader parent) {
        return loaderOf(compileToBytes(sources), parent);
    }

    /** A class loader defining {@code classes} (binary name to class file), child of {@code parent}. */
    public static ClassLoader loaderOf(Map<String, byte[]> classes, ClassLoader parent) {
        return new ByteArrayClassLoader(classes, parent);
    }

    /**
     * Compiles {@code sources} to class files, by binary name.
     *
     * @throws GeneratedCodeException if javac reports an error, with javac's messages for the bug report
     */
    public Map<String, byte[]> compileToBytes(List<Source> sources) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new GeneratedCodeException("no Java compiler in this runtime: masl needs a JDK, not a JRE");
        }
        DiagnosticCollector<JavaFileObject> problems = new DiagnosticCollector<>();
        StandardJavaFileManager standard = javac.getStandardFileManager(problems, null, null);
        ClassesInMemory output = new ClassesInMemory(standard);
        List<JavaFileObject> units = new ArrayList<>();
        for (Source source : sources) {
            units.add(new SourceInMemory(source));
        }
        List<String> options = new ArrayList<>(List.of("-classpath", joinedClassPath(), "-proc:none", "-g", "-nowarn"));
        options.addAll(RELEASE);
        StringWriter javacOutput = new StringWriter();
        boolean compiled = javac.getTask(javacOutput, output, problems, options, null, units).call();
        if (!compiled) {
            StringBuilder report = new StringBuilder("javac rejected the generated code:");
            for (Diagnostic<? extends JavaFileObject> problem : problems.getDiagnostics()) {
                if (problem.getKind() == Diagnostic.Kind.ERROR) {
                    report.append('\n').append(problem);
                }
            }
            throw new GeneratedCodeException(report.toString());
        }
        Map<String, byte[]> classes = new HashMap<>();
        output.classes.forEach((name, file) -> classes.put(name, file.bytes.toByteArray()));
        return classes;
    }

    private String joinedClassPath() {
        List<String> entries = new ArrayList<>(classPath);
        entries.add(System.getProperty("java.class.path"));
        return String.join(File.pathSeparator, entries);
    }

    private static final class SourceInMemory extends SimpleJavaFileObject {
        private final String text;

        SourceInMemory(Source source) {
            super(URI.create("string:///" + source.className().replace('.', '/') + Kind.SOURCE.extension), Kind.SOURCE);
            this.text = source.text();
        }

        @Override
        public CharSequence getCharContent(boolean ignoreEncodingErrors) {
            return text;
        }
    }

    private static final class ClassInMemory extends SimpleJavaFileObject {
        private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();

        ClassInMemory(String className) {
            super(URI.create("bytes:///" + className.replace('.', '/') + Kind.CLASS.extension), Kind.CLASS);
        }

        @Override
        public OutputStream openOutputStream() {
            return bytes;
        }
    }

    private static final class ClassesInMemory extends ForwardingJavaFileManager<StandardJavaFileManager> {
        final Map<String, ClassInMemory> classes = new HashMap<>();

        ClassesInMemory(StandardJavaFileManager standard) {
            super(standard);
        }

        @Override
        public JavaFileObject getJavaFileForOutput(Location location, String className, JavaFileObject.Kind kind,
                FileObject sibling) throws IOException {
            if (kind != JavaFileObject.Kind.CLASS) {
                return super.getJavaFileForOutput(location, className, kind, sibling);
            }
            ClassInMemory file = new ClassInMemory(className);
            classes.put(className, file);
            return file;
        }
    }

    private static final class ByteArrayClassLoader extends ClassLoader {
        private final Map<String, byte[]> classes;

        ByteArrayClassLoader(Map<String, byte[]> classes, ClassLoader parent) {
            super(parent);
            this.classes = Map.copyOf(classes);
        }

        /**
         * The program's own classes are defined here without asking the parent first: no jar of the
         * class path or agent path can stand in for a class the checker accepted, and loading one
         * does not make the parent open every jar looking for it (45 ms of a 0.3 s {@code masl run}
         * from the cache). Every other class is loaded the parent's way.
         */
        @Override
        protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
            if (!classes.containsKey(name)) {
                return super.loadClass(name, resolve);
            }
            synchronized (getClassLoadingLock(name)) {
                Class<?> loaded = findLoadedClass(name);
                if (loaded == null) {
                    loaded = findClass(name);
                }
                if (resolve) {
                    resolveClass(loaded);
                }
                return loaded;
            }
        }

        @Override
        protected Class<?> findClass(String name) throws ClassNotFoundException {
            byte[] bytes = classes.get(name);
            if (bytes == null) {
                throw new ClassNotFoundException(name);
            }
            return defineClass(name, bytes, 0, bytes.length);
        }
    }
}
